// PCG random numbers, bit-exact twins of shaders/common/random.glsl: the same 32-bit unsigned
// arithmetic (wrapping modulo 2^32), so a test can replay any pixel's random stream.
#pragma once

#include <cstdint>

namespace geodesic {

// O'Neill's RXS-M-XS output permutation applied to one step of the 32-bit LCG.
constexpr uint32_t pcg_hash(uint32_t v) {
  const uint32_t state = v * 747796405u + 2891336453u;
  const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// One independent stream per (pixel, sample index, scene seed).
constexpr uint32_t rng_seed(uint32_t pixel, uint32_t sample_index, uint32_t seed) {
  return pcg_hash(pixel ^ pcg_hash(sample_index ^ pcg_hash(seed)));
}

// Advances the stream and returns a uniform number in [0, 1). The top 24 bits of the output
// scaled by 2^-24 are exact in float, so this double equals the shader's float bit for bit.
constexpr double rng_next(uint32_t& state) {
  state = state * 747796405u + 2891336453u;
  uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  word = (word >> 22u) ^ word;
  return static_cast<double>(word >> 8) * (1.0 / 16777216.0);
}

}  // namespace geodesic
