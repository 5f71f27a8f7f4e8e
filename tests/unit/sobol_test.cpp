// The pixel samples' positions (geometry/sobol.h, twin of shaders/common/sobol.glsl; the probe
// test holds them bit for bit): every aligned run of 2^m points of a pixel's sequence is a
// (0, m, 2)-net, and each point, over the pixels' seeds, is uniform (so the estimate stays
// unbiased). Independent random positions fail the first.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "geometry/sobol.h"

namespace geodesic {
namespace {

// Whether the points (32-bit fixed point, or their 24-bit truncations) put exactly one point in
// each of the 2^m elementary rectangles 2^-a x 2^-(m-a), for every a.
bool is_net(const std::vector<SobolPoint>& points, int m, bool truncated) {
  for (int a = 0; a <= m; ++a) {
    std::vector<int> count(size_t(1) << m, 0);
    for (const SobolPoint& p : points) {
      const uint32_t x = truncated ? (p.x >> 8) << 8 : p.x, y = truncated ? (p.y >> 8) << 8 : p.y;
      const uint32_t cx = a == 0 ? 0 : x >> (32 - a), cy = a == m ? 0 : y >> (32 - (m - a));
      if (++count[(size_t(cx) << (m - a)) | cy] > 1) return false;
    }
  }
  return true;
}

TEST(Sobol, EveryAlignedRunOfAPixelsSamplesIsStratifiedInEveryShape) {
  for (uint32_t seed : {0u, 1u, 7u, 0x5bd1e995u, rng_seed(123, 0, 42), rng_seed(123, 1, 42)})
    for (int m = 0; m <= 10; ++m)
      for (uint32_t run : {0u, 1u, 5u, 1000u}) {
        std::vector<SobolPoint> points;
        for (uint32_t i = 0; i < (1u << m); ++i) points.push_back(sobol_sample((run << m) + i, seed));
        EXPECT_TRUE(is_net(points, m, false)) << "seed " << seed << " m " << m << " run " << run;
        EXPECT_TRUE(is_net(points, m, true)) << "seed " << seed << " m " << m << " run " << run;
      }
}

TEST(Sobol, IndependentRandomPositionsAreNotStratified) {  // the check can tell
  uint32_t state = rng_seed(1, 2, 3);
  int nets = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<SobolPoint> points;
    for (int i = 0; i < 16; ++i) {
      const uint32_t x = uint32_t(rng_next(state) * 4294967296.0), y = uint32_t(rng_next(state) * 4294967296.0);
      points.push_back({x, y});
    }
    nets += is_net(points, 4, false);
  }
  EXPECT_EQ(nets, 0);
}

TEST(Sobol, EachPointIsUniformOverThePixelsSeeds) {
  // Point i of 65536 pixels' sequences: a chi-square over an 8x8 grid (63 degrees of freedom;
  // 110 is its 0.9999 quantile), and the mean of each coordinate within 5 sigma of 1/2.
  for (uint32_t index : {0u, 1u, 2u, 3u, 17u, 1023u}) {
    std::array<int, 64> cells{};
    double sum_u = 0, sum_v = 0;
    const int n = 65536;
    for (int pixel = 0; pixel < n; ++pixel) {
      const SobolPoint p = sobol_sample(index, rng_seed(uint32_t(pixel), 0, 42));
      ++cells[(p.x >> 29) * 8 + (p.y >> 29)];
      sum_u += p.u();
      sum_v += p.v();
    }
    double chi2 = 0;
    for (int c : cells) chi2 += (c - n / 64.0) * (c - n / 64.0) / (n / 64.0);
    EXPECT_LT(chi2, 110) << "index " << index;
    const double sigma = std::sqrt(1.0 / 12 / n);
    EXPECT_NEAR(sum_u / n, 0.5, 5 * sigma) << "index " << index;
    EXPECT_NEAR(sum_v / n, 0.5, 5 * sigma) << "index " << index;
  }
}

TEST(Sobol, TheTwinsBitArithmeticMatchesKnownValues) {
  static_assert(reverse_bits(1u) == 0x80000000u);
  static_assert(reverse_bits(0x0000ffffu) == 0xffff0000u);
  // Sobol's second dimension: 1/2, 3/4, 1/4, 5/8, 1/8 for indices 1..5.
  static_assert(sobol_second(1) == 0x80000000u);
  static_assert(sobol_second(2) == 0xc0000000u);
  static_assert(sobol_second(3) == 0x40000000u);
  static_assert(sobol_second(4) == 0xa0000000u);
  static_assert(sobol_second(5) == 0x20000000u);
  SUCCEED();
}

}  // namespace
}  // namespace geodesic
