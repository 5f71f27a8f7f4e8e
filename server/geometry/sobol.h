// Owen-scrambled 2-D Sobol points, bit-exact twins of shaders/common/sobol.glsl (every sample
// dimension of a camera path): the same 32-bit unsigned arithmetic, so a test can replay any pixel's
// points and check their stratification.
#pragma once

#include <cstdint>

#include "geometry/random.h"

namespace geodesic {

constexpr uint32_t reverse_bits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

constexpr uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// Owen scrambling of a 32-bit fixed-point number: each bit flipped by a hash of those above it.
constexpr uint32_t nested_uniform_scramble(uint32_t x, uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

// Sobol's second dimension (direction numbers v_k = v_{k-1} ^ (v_{k-1} >> 1), v_0 = 2^31):
// Pascal's triangle mod 2 times the index, in bit-reversed order by five masked shifts.
constexpr uint32_t pascal_product(uint32_t v) {
  v ^= v >> 16;
  v ^= (v & 0xff00ff00u) >> 8;
  v ^= (v & 0xf0f0f0f0u) >> 4;
  v ^= (v & 0xccccccccu) >> 2;
  v ^= (v & 0xaaaaaaaau) >> 1;
  return v;
}

constexpr uint32_t sobol_second(uint32_t index) { return reverse_bits(pascal_product(index)); }

struct SobolPoint {
  uint32_t x, y;  // 32-bit fixed point; the shader keeps the top 24 bits
  double u() const { return double(x >> 8) * (1.0 / 16777216.0); }
  double v() const { return double(y >> 8) * (1.0 / 16777216.0); }
};

// The seed of the sequence of dimension pair `pair` (0 the pixel position, then 1 + 4 per
// bounce: light choice, point on the light, BSDF direction, lobe and Russian roulette) of the
// samples of one parity of a pixel (shaders/common/sampler.glsl), under the scene's seed.
// Pair 0's seed plus a Weyl step per pair (sobol_sample hashes it three times over).
constexpr uint32_t path_sampler_seed(uint32_t pixel, uint32_t parity, uint32_t pair, uint32_t seed) {
  return rng_seed(pixel, parity, seed ^ 0x5bd1e995u) + pair * 0x9e3779b9u;
}

// Point `index` of the scrambled, shuffled sequence of `seed` (the shader's sobolSample).
constexpr SobolPoint sobol_sample(uint32_t index, uint32_t seed) {
  const uint32_t shuffled = nested_uniform_scramble(index, pcg_hash(seed));
  return {reverse_bits(laine_karras_permutation(shuffled, pcg_hash(seed ^ 0x9e3779b9u))),
          reverse_bits(laine_karras_permutation(pascal_product(shuffled), pcg_hash(seed ^ 0x7f4a7c15u)))};
}

}  // namespace geodesic
