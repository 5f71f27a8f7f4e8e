// The sample dimensions of camera paths (geometry/sobol.h, twin of shaders/common/sobol.glsl
// and sampler.glsl; the probe test holds them bit for bit): every aligned run of 2^m points of
// a pixel's sequence is a (0, m, 2)-net, in every pair of dimensions of every bounce; each
// point, over the pixels' seeds, is uniform (so the estimate stays unbiased); different pairs
// and the two halves are independent. Independent random positions fail the first.
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

// Every pair of dimensions of a path (the pixel position, then four per bounce) is a net in
// every aligned run of each half's samples, and pair 0 is the sequence the pixel positions had.
TEST(Sobol, EveryDimensionPairOfAPathIsStratified) {
  EXPECT_EQ(path_sampler_seed(77, 1, 0, 42), rng_seed(77, 1, 42 ^ 0x5bd1e995u));
  for (uint32_t parity : {0u, 1u})
    for (uint32_t pair = 0; pair < 1 + 4 * 8; ++pair)
      for (int m : {2, 5, 8}) {
        std::vector<SobolPoint> points;
        const uint32_t seed = path_sampler_seed(1234, parity, pair, 42);
        for (uint32_t i = 0; i < (1u << m); ++i) points.push_back(sobol_sample((3u << m) + i, seed));
        EXPECT_TRUE(is_net(points, m, true)) << "parity " << parity << " pair " << pair << " m " << m;
      }
}

// The pairs are paired at random: across 256 samples of a pixel, the first coordinates of two
// different pairs (or of one pair in the two halves) are uncorrelated (|r| below 4.5 sigma of
// zero, 1/sqrt(256) each); the same pair is, of course, itself.
TEST(Sobol, DimensionPairsAndHalvesAreMutuallyIndependent) {
  auto coordinates = [](uint32_t parity, uint32_t pair, uint32_t pixel) {
    std::vector<double> u;
    for (uint32_t i = 0; i < 256; ++i) u.push_back(sobol_sample(i, path_sampler_seed(pixel, parity, pair, 9)).u());
    return u;
  };
  auto correlation = [](const std::vector<double>& a, const std::vector<double>& b) {
    double sa = 0, sb = 0, sab = 0, saa = 0, sbb = 0;
    const double n = double(a.size());
    for (size_t i = 0; i < a.size(); ++i) {
      sa += a[i]; sb += b[i]; sab += a[i] * b[i]; saa += a[i] * a[i]; sbb += b[i] * b[i];
    }
    return (sab / n - sa * sb / n / n) /
           std::sqrt((saa / n - sa * sa / n / n) * (sbb / n - sb * sb / n / n));
  };
  const double bound = 4.5 / std::sqrt(256.0);
  for (uint32_t pixel : {0u, 5u, 99999u}) {
    for (uint32_t pair = 0; pair < 12; ++pair) {
      EXPECT_LT(std::abs(correlation(coordinates(0, pair, pixel), coordinates(0, pair + 1, pixel))), bound)
          << "pixel " << pixel << " pairs " << pair << ", " << pair + 1;
      EXPECT_LT(std::abs(correlation(coordinates(0, pair, pixel), coordinates(1, pair, pixel))), bound)
          << "pixel " << pixel << " pair " << pair << ", even and odd";
    }
    EXPECT_NEAR(correlation(coordinates(1, 3, pixel), coordinates(1, 3, pixel)), 1.0, 1e-12);
  }
}

// The five masked shifts equal the definition by direction numbers, bit by bit.
TEST(Sobol, SecondDimensionEqualsItsDirectionNumbers) {
  auto by_directions = [](uint32_t index) {
    uint32_t v = 0x80000000u, result = 0;
    for (; index != 0; index >>= 1, v ^= v >> 1)
      if (index & 1u) result ^= v;
    return result;
  };
  uint32_t state = rng_seed(5, 6, 7);
  for (uint32_t i = 0; i < 70000; ++i) {
    const uint32_t index = i < 65536 ? i : uint32_t(rng_next(state) * 4294967296.0) | 0x80000001u;
    ASSERT_EQ(sobol_second(index), by_directions(index)) << "index " << index;
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
