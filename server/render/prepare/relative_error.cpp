#include "render/prepare/relative_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/sampling.h"

namespace geodesic {
namespace {

double luminance_of(const float* rgb) { return luminance(Vec3(rgb[0], rgb[1], rgb[2])); }

// Sums of squared error and of squared signal; their ratio's square root is the measure.
struct RelativeError {
  double squared_error = 0;
  double signal = 0;

  double value() const { return signal > 0 ? std::sqrt(squared_error / signal) : -1; }
};

}  // namespace

double relative_rmse(const Image& image, const Image& reference) {
  if (image.width != reference.width || image.height != reference.height)
    throw std::invalid_argument("relative_rmse: images differ in size");
  RelativeError e;
  const size_t pixels = size_t(image.width) * image.height;
  for (size_t p = 0; p < pixels; ++p) {
    const double l = luminance_of(&image.rgb[p * 3]), r = luminance_of(&reference.rgb[p * 3]);
    e.squared_error += (l - r) * (l - r);
    e.signal += r * r;
  }
  return e.value();
}

double estimated_relative_rmse(const float* even, const float* odd, size_t pixels) {
  RelativeError e;
  for (size_t p = 0; p < pixels; ++p) {
    const double n_a = even[p * 4 + 3], n_b = odd[p * 4 + 3];
    if (n_a == 0 || n_b == 0) return -1;
    const double sum_a = luminance_of(even + p * 4), sum_b = luminance_of(odd + p * 4);
    const double a = sum_a / n_a, b = sum_b / n_b, c = (sum_a + sum_b) / (n_a + n_b);
    e.squared_error += (a - b) * (a - b) * (n_a * n_b / ((n_a + n_b) * (n_a + n_b)));
    e.signal += c * c;
  }
  // sum_p c_p^2 overstates sum_p mu_p^2 by the variance of the c_p, i.e. by squared_error:
  // take it off (but keep at least half, where noise drowns the signal).
  e.signal = std::max(e.signal - e.squared_error, e.signal / 2);
  return e.value();
}

}  // namespace geodesic
