// PCG random numbers (O'Neill's RXS-M-XS output on a 32-bit LCG): one independent stream per
// (pixel, sample index, scene seed), so progressive frames stay unbiased.
#ifndef RANDOM_GLSL
#define RANDOM_GLSL

uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

uint rngSeed(uint pixel, uint sampleIndex, uint seed) {
  return pcgHash(pixel ^ pcgHash(sampleIndex ^ pcgHash(seed)));
}

// Uniform in [0, 1).
float rngNext(inout uint state) {
  state = state * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  word = (word >> 22u) ^ word;
  return float(word >> 8) * (1.0 / 16777216.0);
}

// Russian roulette on the uniform u: a path survives with probability q = min(1, max
// throughput) and is divided by q, so the expectation is unchanged and dim paths end early.
bool survivesRussianRoulette(inout vec3 throughput, float u) {
  float q = min(1.0, max(throughput.r, max(throughput.g, throughput.b)));
  if (u >= q) return false;
  throughput /= q;
  return true;
}

#endif
