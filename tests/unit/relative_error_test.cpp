// The error measure (server/render/prepare/relative_error.h): the relative RMSE against a reference,
// and its estimate from two halves of the samples, checked on synthetic pixels whose noise is
// known.
#include "render/prepare/relative_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace geodesic {
namespace {

Image grey(std::vector<float> values) {
  Image image{int(values.size()), 1, {}};
  for (float v : values) image.rgb.insert(image.rgb.end(), {v, v, v});
  return image;
}

TEST(RelativeRmse, IsTheRmsLuminanceDifferenceOverTheRmsReference) {
  // Differences 0.3 and -0.4 over references 1 and 2: sqrt((0.09 + 0.16) / (1 + 4)).
  EXPECT_NEAR(relative_rmse(grey({1.3f, 1.6f}), grey({1, 2})), std::sqrt(0.25 / 5), 1e-6);
  EXPECT_DOUBLE_EQ(relative_rmse(grey({1, 2}), grey({1, 2})), 0.0);
  // Luminance weights: a pure blue error of 1 counts 0.0722.
  Image blue = grey({1}), ref = grey({1});
  blue.rgb[2] += 1;
  EXPECT_NEAR(relative_rmse(blue, ref), 0.0722, 1e-6);
  EXPECT_LT(relative_rmse(grey({1}), grey({0})), 0);  // black reference: undefined
  EXPECT_THROW(relative_rmse(grey({1, 2}), grey({1})), std::invalid_argument);
}

// Halves of n_even and n_odd Gaussian samples per pixel (true value mu_p, deviation sigma_p):
// the estimate must match the expected relative RMSE of the combined mean,
// sqrt(sum sigma_p^2 / (n_even + n_odd) / sum mu_p^2), and the realised error.
void check_estimate(int n_even, int n_odd) {
  constexpr size_t kPixels = 40000;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> level(0.2, 2.0);
  std::normal_distribution<double> unit;
  std::vector<float> even(kPixels * 4), odd(kPixels * 4);
  std::vector<float> mean(kPixels * 3), truth(kPixels * 3);
  double variance = 0, signal = 0;
  for (size_t p = 0; p < kPixels; ++p) {
    const double mu = level(rng), sigma = 0.5 * mu * level(rng);
    auto add = [&](float* half, int n) {
      for (int k = 0; k < n; ++k) {
        const float v = float(mu + sigma * unit(rng));
        for (int c = 0; c < 3; ++c) half[c] += v;
        half[3] += 1;
      }
    };
    add(&even[p * 4], n_even);
    add(&odd[p * 4], n_odd);
    for (int c = 0; c < 3; ++c) {
      mean[p * 3 + c] = (even[p * 4 + c] + odd[p * 4 + c]) / float(n_even + n_odd);
      truth[p * 3 + c] = float(mu);
    }
    variance += sigma * sigma / (n_even + n_odd);
    signal += mu * mu;
  }
  ASSERT_EQ(even[3], float(n_even));
  ASSERT_EQ(odd[3], float(n_odd));
  const double estimate = estimated_relative_rmse(even.data(), odd.data(), kPixels);
  const double expected = std::sqrt(variance / signal);
  const double realised = relative_rmse({int(kPixels), 1, mean}, {int(kPixels), 1, truth});
  EXPECT_NEAR(estimate / expected, 1.0, 0.02) << n_even << "+" << n_odd;
  EXPECT_NEAR(realised / expected, 1.0, 0.02) << n_even << "+" << n_odd;
}

TEST(EstimatedRelativeRmse, MatchesTheErrorOfTheMeanForEqualHalves) { check_estimate(4, 4); }

// An odd sample count leaves the even half one sample ahead: a quarter of (a - b)^2 would
// overstate the variance of the mean by 12.5 % at 2 + 1 samples.
TEST(EstimatedRelativeRmse, WeighsUnequalHalvesByTheirCounts) {
  check_estimate(2, 1);
  check_estimate(5, 4);
}

TEST(EstimatedRelativeRmse, IsUnknownUntilBothHalvesHaveASampleAndZeroWithoutNoise) {
  std::vector<float> even = {1, 1, 1, 1, 2, 2, 2, 2}, odd = {1, 1, 1, 1, 0, 0, 0, 0};
  EXPECT_LT(estimated_relative_rmse(even.data(), odd.data(), 2), 0);
  odd = {1, 1, 1, 1, 2, 2, 2, 2};
  EXPECT_DOUBLE_EQ(estimated_relative_rmse(even.data(), odd.data(), 2), 0.0);
}

}  // namespace
}  // namespace geodesic
