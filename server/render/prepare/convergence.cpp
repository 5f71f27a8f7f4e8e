#include "render/prepare/convergence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace geodesic {

const char* StopCondition::met(const ErrorSample& now) const {
  if (spp && now.spp >= *spp) return "spp";
  if (seconds && now.seconds >= *seconds) return "seconds";
  // Below 4 samples per half the estimate itself is too noisy to stop on.
  if (target_error && now.spp >= 8 && now.error >= 0 && now.error <= *target_error)
    return "target_error";
  return nullptr;
}

double StopCondition::progress(const ErrorSample& now) const {
  double p = 0;
  if (spp) p = std::max(p, double(now.spp) / *spp);
  if (seconds) p = std::max(p, now.seconds / *seconds);
  // Error falls as 1/sqrt(spp): (target / error)^2 is the fraction of samples done.
  if (target_error && now.error > 0) p = std::max(p, std::pow(*target_error / now.error, 2));
  return std::clamp(p, 0.0, 1.0);
}

nlohmann::ordered_json StopCondition::to_json() const {
  auto or_null = [](const auto& v) { return v ? nlohmann::ordered_json(*v) : nullptr; };
  return {{"spp", or_null(spp)},
          {"seconds", or_null(seconds)},
          {"target_error", or_null(target_error)}};
}

nlohmann::ordered_json ConvergenceLog::to_json() const {
  nlohmann::ordered_json series = nlohmann::ordered_json::array();
  for (const ErrorSample& s : samples_) {
    nlohmann::ordered_json point;
    point["seconds"] = s.seconds;
    point["spp"] = s.spp;
    point["estimated_error"] = s.error >= 0 ? nlohmann::ordered_json(s.error) : nullptr;
    series.push_back(point);
  }
  return {{"series", series}};
}

std::string ConvergenceLog::to_csv() const {
  std::string csv = "seconds,spp,estimated_error\n";
  char line[96];
  for (const ErrorSample& s : samples_) {
    if (s.error >= 0)
      std::snprintf(line, sizeof line, "%.6f,%u,%.8g\n", s.seconds, s.spp, s.error);
    else
      std::snprintf(line, sizeof line, "%.6f,%u,\n", s.seconds, s.spp);
    csv += line;
  }
  return csv;
}

}  // namespace geodesic
