// The sample dimensions of one camera path: padded Owen-scrambled Sobol points (pbrt-v4's
// PaddedSobolSampler). Each pair of dimensions a path asks for (the pixel position, then per
// bounce the light choice, the point on the light, the BSDF direction, the lobe and Russian
// roulette) is its own 2-D Sobol sequence for the pixel, scrambled and index-shuffled under a
// seed of its own (common/sobol.glsl): every aligned run of 2^m samples of a pixel is then a
// (0,m,2)-net in each pair, and the pairs are paired at random. Dimensions are allotted per
// bounce, not as they are consumed, so a branch that skips a draw shifts nothing after it.
// The even- and odd-numbered samples of a pixel are two independent sequences (the parity is
// in every seed), so the two accumulation halves stay independent unbiased estimates and their
// difference the error estimate (docs/numerics.md). Twin: server/geometry/sobol.h
// (path_sampler_seed, sobol_sample).
#ifndef SAMPLER_GLSL
#define SAMPLER_GLSL

struct PathSampler {
  uint seed;   // pathSamplerSeed of pair 0 for the pixel and the sample's parity (which half)
  uint index;  // sample index >> 1: this sample's point in its half's sequences
};

// Pairs of dimensions per bounce: light choice (emitter, image), point on the light, BSDF
// direction, (lobe, Russian roulette). Pair 0 is the pixel position.
const uint PAIRS_PER_BOUNCE = 4u;
const uint PAIR_LIGHT_CHOICE = 0u;
const uint PAIR_LIGHT_POINT = 1u;
const uint PAIR_DIRECTION = 2u;
const uint PAIR_LOBE_ROULETTE = 3u;

PathSampler pathSampler(uint pixel, uint sampleIndex) {
  return PathSampler(pathSamplerSeed(pixel, sampleIndex & 1u, 0u, frame.seed), sampleIndex >> 1u);
}

vec2 samplePair(PathSampler s, uint pair) {
  return sobolSample(s.index, pathPairSeed(s.seed, pair));
}

// Pair `which` (PAIR_*) of bounce `depth`.
vec2 bounceSample(PathSampler s, uint depth, uint which) {
  return samplePair(s, 1u + depth * PAIRS_PER_BOUNCE + which);
}

#endif
