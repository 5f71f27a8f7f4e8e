// Pearson's chi-square test of a direction sampler against the density it claims: directions
// binned by (cos theta, phi) about an axis over the whole sphere, each bin's expected count
// integrated from the density (midpoint rule: a density with a jump should put it on a bin
// edge, cos theta = -1 + i / 12), bins expecting fewer than 5 pooled, and samples the sampler
// rejects compared with the density's missing mass.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <vector>

#include <boost/math/special_functions/gamma.hpp>

#include "geometry/random.h"
#include "geometry/vec.h"

namespace geodesic {

using DirectionSampler = std::function<std::optional<Vec3>(double, double)>;
using DirectionDensity = std::function<double(const Vec3&)>;

// The p-value of the hypothesis that `sample` draws from `density` (solid angle).
inline double chi_square_p(const Vec3& axis, const DirectionSampler& sample,
                           const DirectionDensity& density, int samples = 400000) {
  constexpr int kCos = 24, kPhi = 16, kSubCos = 64, kSubPhi = 8;
  constexpr double kPi = std::numbers::pi;
  const Vec3 x = normalize(cross(axis, std::abs(axis.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
  const Vec3 y = cross(axis, x);
  auto direction = [&](double c, double phi) {
    const double s = std::sqrt(std::max(0.0, 1 - c * c));
    return s * std::cos(phi) * x + s * std::sin(phi) * y + c * axis;
  };
  std::vector<double> observed(kCos * kPhi + 1, 0), expected(kCos * kPhi + 1, 0);
  uint32_t state = rng_seed(11, 22, 33);
  for (int i = 0; i < samples; ++i) {
    const double u1 = rng_next(state), u2 = rng_next(state);
    const std::optional<Vec3> w = sample(u1, u2);
    if (!w) {
      ++observed.back();
      continue;
    }
    const double c = std::clamp(dot(*w, axis), -1.0, 1.0);
    const double phi = std::atan2(dot(*w, y), dot(*w, x)) + kPi;
    const int a = std::min(kCos - 1, int((c + 1) / 2 * kCos));
    const int b = std::min(kPhi - 1, int(phi / (2 * kPi) * kPhi));
    ++observed[a * kPhi + b];
  }
  // Expected counts: midpoint rule in (cos theta, phi), whose measure is solid angle.
  double mass = 0;
  for (int a = 0; a < kCos; ++a)
    for (int b = 0; b < kPhi; ++b) {
      double integral = 0;
      const double dc = 2.0 / kCos / kSubCos, dphi = 2 * kPi / kPhi / kSubPhi;
      for (int i = 0; i < kSubCos; ++i)
        for (int j = 0; j < kSubPhi; ++j)
          integral += density(direction(-1 + (a * kSubCos + i + 0.5) * dc,
                                        (b * kSubPhi + j + 0.5) * dphi - kPi)) * dc * dphi;
      expected[a * kPhi + b] = integral * samples;
      mass += integral;
    }
  // The quadrature's own error in the total is ~1e-4: a smaller deficit is not missing mass.
  expected.back() = 1 - mass > 2e-3 ? (1 - mass) * samples : 0;
  // Pool the small bins so the statistic stays chi-square distributed.
  double chi2 = 0, pooled_observed = 0, pooled_expected = 0;
  int bins = 0;
  for (size_t i = 0; i < expected.size(); ++i) {
    if (expected[i] < 5) {
      pooled_observed += observed[i];
      pooled_expected += expected[i];
      continue;
    }
    chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++bins;
  }
  if (pooled_expected >= 5) {
    chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
            pooled_expected;
    ++bins;
  } else if (pooled_observed > 5 + 10 * pooled_expected) {
    return 0;  // samples where the density says there are (almost) none
  }
  return boost::math::gamma_q((bins - 1) / 2.0, chi2 / 2);
}

}  // namespace geodesic
