// Error against run time: the series every render records, and the stop conditions that end
// a render (samples per pixel, seconds, or an estimated error to reach).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace geodesic {

// One point of a render's progress. `error` is Renderer::estimated_error(): the relative RMS
// error estimated from the even/odd sample halves (docs/numerics.md), negative before both
// halves have a sample.
struct ErrorSample {
  double seconds = 0;
  uint32_t spp = 0;
  double error = -1;
};

// At least one field is set; a render stops at the first condition met.
struct StopCondition {
  std::optional<uint32_t> spp;
  std::optional<double> seconds;
  std::optional<double> target_error;

  bool reached(const ErrorSample& now) const { return met(now) != nullptr; }
  // The first condition `now` meets, by its JSON name ("spp", "seconds", "target_error"), or
  // nullptr while none is.
  const char* met(const ErrorSample& now) const;
  // Progress in [0, 1] towards the nearest condition (error on a 1/sqrt(spp) scale).
  double progress(const ErrorSample& now) const;
  // {"spp", "seconds", "target_error"}: each limit, null where unset.
  nlohmann::ordered_json to_json() const;
};

class ConvergenceLog {
 public:
  void record(const ErrorSample& sample) { samples_.push_back(sample); }
  const std::vector<ErrorSample>& samples() const { return samples_; }
  bool empty() const { return samples_.empty(); }
  const ErrorSample& last() const { return samples_.back(); }

  // {"series": [{"seconds", "spp", "estimated_error"}...]}; error is null while unknown.
  nlohmann::ordered_json to_json() const;
  // "seconds,spp,estimated_error" then one line per sample (empty field while unknown).
  std::string to_csv() const;

 private:
  std::vector<ErrorSample> samples_;
};

}  // namespace geodesic
