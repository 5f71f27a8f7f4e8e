// The double-precision sampling and random-number references: the tangent frame, the
// cosine-weighted hemisphere (its density checked with a chi-square test) and the PCG twin.
#include "geometry/random.h"
#include "geometry/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>
#include "test_constants.h"

namespace geodesic {
namespace {

using test::kPi;

std::vector<Vec3> test_normals() {
  std::vector<Vec3> normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, -0.0}, {0, 1, 0},
                               normalize(Vec3{1e-4, -2e-4, -1}), normalize(Vec3{0.3, -0.5, 0.8})};
  std::mt19937_64 gen(5);
  std::normal_distribution<double> g;
  for (int i = 0; i < 1000; ++i) normals.push_back(normalize(Vec3{g(gen), g(gen), g(gen)}));
  return normals;
}

TEST(Sampling, OrthonormalBasisIsARightHandedFrame) {
  for (const Vec3& n : test_normals()) {
    const TangentFrame f = orthonormal_basis(n);
    EXPECT_NEAR(dot(f.tangent, f.tangent), 1, 1e-14);
    EXPECT_NEAR(dot(f.bitangent, f.bitangent), 1, 1e-14);
    EXPECT_NEAR(dot(f.tangent, f.bitangent), 0, 1e-14);
    EXPECT_NEAR(dot(f.tangent, n), 0, 1e-14);
    EXPECT_NEAR(length(cross(f.tangent, f.bitangent) - n), 0, 1e-14);
  }
}

TEST(Sampling, CosineSamplesAreUnitAndInTheHemisphere) {
  uint32_t state = rng_seed(0, 0, 99);
  for (const Vec3& n : test_normals())
    for (int i = 0; i < 200; ++i) {
      const double u1 = rng_next(state), u2 = rng_next(state);
      const Vec3 w = sample_cosine_hemisphere(n, u1, u2);
      EXPECT_NEAR(length(w), 1, 1e-14);
      EXPECT_GE(dot(w, n), -1e-15);
      EXPECT_NEAR(dot(w, n), std::sqrt(1 - u1), 1e-12);  // cos(theta) is set by u1 alone
    }
}

// Pearson's chi-square of `sampler`'s directions around n against the density cos(theta)/pi,
// in 10 bins of cos(theta) by 8 of phi; returns the p-value (Wilson-Hilferty approximation).
double cosine_chi_square_p(const Vec3& n, const std::function<Vec3(double, double)>& sampler) {
  constexpr int kCos = 10, kPhi = 8, kSamples = 200000;
  // An azimuth frame independent of orthonormal_basis.
  const Vec3 x = normalize(cross(n, std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
  const Vec3 y = cross(n, x);
  std::vector<int> counts(kCos * kPhi, 0);
  uint32_t state = rng_seed(1, 2, 3);
  for (int i = 0; i < kSamples; ++i) {
    const double u1 = rng_next(state), u2 = rng_next(state);
    const Vec3 w = sampler(u1, u2);
    const double phi = std::atan2(dot(w, y), dot(w, x)) + kPi;
    const int a = std::min(kCos - 1, int(dot(w, n) * kCos));
    const int b = std::min(kPhi - 1, int(phi / (2 * kPi) * kPhi));
    ++counts[a * kPhi + b];
  }
  double chi2 = 0;
  for (int a = 0; a < kCos; ++a) {
    // P(c0 <= cos < c1) = c1^2 - c0^2 under cos/pi, shared evenly over the phi bins.
    const double c0 = double(a) / kCos, c1 = double(a + 1) / kCos;
    const double expected = kSamples * (c1 * c1 - c0 * c0) / kPhi;
    for (int b = 0; b < kPhi; ++b) {
      const double diff = counts[a * kPhi + b] - expected;
      chi2 += diff * diff / expected;
    }
  }
  const double k = kCos * kPhi - 1;  // degrees of freedom
  const double z = (std::cbrt(chi2 / k) - (1 - 2 / (9 * k))) / std::sqrt(2 / (9 * k));
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

TEST(Sampling, CosineSamplesFollowCosineOverPi) {
  for (const Vec3& n : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, normalize(Vec3{0.3, -0.5, -0.8})}) {
    const auto cosine = [&](double u1, double u2) { return sample_cosine_hemisphere(n, u1, u2); };
    EXPECT_GT(cosine_chi_square_p(n, cosine), 0.001) << n.x << " " << n.y << " " << n.z;
  }
}

// The same test rejects a uniform hemisphere, so passing it means something.
TEST(Sampling, ChiSquareRejectsUniformHemisphere) {
  const Vec3 n{0, 0, 1};
  const auto uniform = [](double u1, double u2) {
    const double z = u1, r = std::sqrt(1 - z * z), phi = 2 * kPi * u2;
    return Vec3{r * std::cos(phi), r * std::sin(phi), z};
  };
  EXPECT_LT(cosine_chi_square_p(n, uniform), 1e-9);
}

TEST(Sampling, CosinePdfIsNormalisedAndZeroBelow) {
  const Vec3 n = normalize(Vec3{1, 2, -2});
  EXPECT_DOUBLE_EQ(cosine_hemisphere_pdf(n, n), 1 / kPi);
  EXPECT_EQ(cosine_hemisphere_pdf(n, -n), 0.0);
  // Midpoint rule over the whole sphere in (theta, phi) about n.
  const TangentFrame f = orthonormal_basis(n);
  constexpr int kSteps = 400;
  constexpr double kCell = (kPi / kSteps) * (2 * kPi / kSteps);
  double integral = 0;
  for (int i = 0; i < kSteps; ++i)
    for (int j = 0; j < kSteps; ++j) {
      const double theta = kPi * (i + 0.5) / kSteps, phi = 2 * kPi * (j + 0.5) / kSteps;
      const Vec3 w = std::sin(theta) * (std::cos(phi) * f.tangent + std::sin(phi) * f.bitangent) +
                     std::cos(theta) * n;
      integral += cosine_hemisphere_pdf(n, w) * std::sin(theta) * kCell;
    }
  EXPECT_NEAR(integral, 1.0, 1e-4);
}

TEST(Sampling, LuminanceWeightsSumToOne) {
  EXPECT_NEAR(luminance({1, 1, 1}), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(luminance({1, 0, 0}), 0.2126);
  EXPECT_DOUBLE_EQ(luminance({0, 2, 0}), 2 * 0.7152);
}

// Expected values worked out from the formulas in shaders/common/random.glsl independently
// (Python, arbitrary-precision integers masked to 32 bits).
static_assert(pcg_hash(0u) == 129708002u);
static_assert(pcg_hash(1u) == 2831084092u);
static_assert(pcg_hash(0x80000000u) == 566699590u);
static_assert(pcg_hash(0xFFFFFFFFu) == 3861530882u);
static_assert(rng_seed(7, 3, 42) == 2300026028u);

TEST(Random, StreamMatchesKnownValues) {
  uint32_t state = rng_seed(7, 3, 42);
  EXPECT_EQ(rng_next(state), 958967 / 16777216.0);
  EXPECT_EQ(state, 2113143969u);
  EXPECT_EQ(rng_next(state), 14503920 / 16777216.0);
  EXPECT_EQ(state, 2010539994u);
  EXPECT_EQ(rng_next(state), 1603527 / 16777216.0);
  EXPECT_EQ(state, 3280473639u);
}

TEST(Random, DrawsAreUniformInTheHalfOpenUnitInterval) {
  uint32_t state = rng_seed(123, 0, 0);
  constexpr int kDraws = 1000000;
  double sum = 0, sum_squares = 0;
  for (int i = 0; i < kDraws; ++i) {
    const double x = rng_next(state);
    ASSERT_GE(x, 0.0);
    ASSERT_LT(x, 1.0);
    ASSERT_EQ(double(float(x)), x);  // exact in float, as the shader's value
    sum += x;
    sum_squares += x * x;
  }
  // Mean 1/2 and variance 1/12, each within about five standard errors.
  const double mean = sum / kDraws;
  EXPECT_NEAR(mean, 0.5, 5 * std::sqrt(1.0 / 12 / kDraws));
  EXPECT_NEAR(sum_squares / kDraws - mean * mean, 1.0 / 12, 5 * std::sqrt(1.0 / 180 / kDraws));
}

}  // namespace
}  // namespace geodesic
