#include "render/prepare/exposure.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geodesic {

double automatic_stops(const Image& image) {
  constexpr double kDark = 1e-6;
  double log_sum = 0;
  size_t lit = 0;
  for (size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    const double y = 0.2126 * image.rgb[i] + 0.7152 * image.rgb[i + 1] + 0.0722 * image.rgb[i + 2];
    if (!(y > kDark) || !std::isfinite(y)) continue;
    log_sum += std::log(y);
    ++lit;
  }
  if (lit == 0) return 0;
  const double log_average = log_sum / double(lit);
  const double stops = std::log2(kMiddleGrey) - log_average / std::log(2.0);
  return std::clamp(stops, -kMaxExposureStops, kMaxExposureStops);
}

double exposure_stops(const Exposure& exposure, const Image& image) {
  return exposure.automatic ? automatic_stops(image) : exposure.stops;
}

Exposure parse_exposure(const std::string& text) {
  if (text == "auto") return {0, true};
  size_t used = 0;
  double stops = 0;
  try {
    stops = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !(std::abs(stops) <= kMaxExposureStops))
    throw std::invalid_argument("must be a number of stops in [-20, 20] or \"auto\", not \"" +
                                text + "\"");
  return {stops, false};
}

float exposure_scale(double stops) { return float(std::exp2(stops)); }

}  // namespace geodesic
