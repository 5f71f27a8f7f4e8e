// Low-discrepancy pixel samples: the first two dimensions of Sobol's sequence (a (0,2)-sequence:
// every aligned run of 2^m points puts exactly one point in each of the 2^m elementary
// rectangles of each shape), Owen-scrambled with hash-based nested uniform scrambling (Laine
// and Karras 2011, as Burley 2020 uses it), the index shuffled the same way, all seeded per
// pixel. Each run of 2^m samples of a pixel is thus stratified and still uniformly distributed,
// so the estimate stays unbiased. Twin: server/geometry/sobol.h.
#ifndef SOBOL_GLSL
#define SOBOL_GLSL

uint laineKarrasPermutation(uint x, uint seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// Owen scrambling of a 32-bit fixed-point number in [0, 1): each bit flipped by a hash of the
// bits above it.
uint nestedUniformScramble(uint x, uint seed) {
  return bitfieldReverse(laineKarrasPermutation(bitfieldReverse(x), seed));
}

// Sobol's second dimension (primitive polynomial x + 1) has direction numbers v_k = v_{k-1} ^
// (v_{k-1} >> 1) from v_0 = 2^31: its generator matrix is Pascal's triangle mod 2, whose
// product with the index, in bit-reversed order, takes five masked shifts instead of a loop
// over the index's bits. The first dimension is the bit reversal of the index.
uint pascalProduct(uint v) {
  v ^= v >> 16u;
  v ^= (v & 0xff00ff00u) >> 8u;
  v ^= (v & 0xf0f0f0f0u) >> 4u;
  v ^= (v & 0xccccccccu) >> 2u;
  v ^= (v & 0xaaaaaaaau) >> 1u;
  return v;
}

uint sobolSecond(uint index) { return bitfieldReverse(pascalProduct(index)); }

// Point `index` of the scrambled, shuffled sequence of `seed`, in 32-bit fixed point.
uvec2 sobolBits(uint index, uint seed) {
  uint shuffled = nestedUniformScramble(index, pcgHash(seed));
  // The first dimension is the reversed index, so its scramble needs no reversal going in:
  // nestedUniformScramble(bitfieldReverse(i), h) = bitfieldReverse(laineKarrasPermutation(i, h)).
  // The same for the second, whose reversal is pascalProduct itself.
  return uvec2(bitfieldReverse(laineKarrasPermutation(shuffled, pcgHash(seed ^ 0x9e3779b9u))),
               bitfieldReverse(laineKarrasPermutation(pascalProduct(shuffled), pcgHash(seed ^ 0x7f4a7c15u))));
}

// The seed of the sequence of dimension pair `pair` of a pixel's half (common/sampler.glsl):
// that of pair 0 plus a Weyl step per pair (sobolBits hashes it three times over).
uint pathPairSeed(uint pairZeroSeed, uint pair) { return pairZeroSeed + pair * 0x9e3779b9u; }

uint pathSamplerSeed(uint pixel, uint parity, uint pair, uint seed) {
  return pathPairSeed(rngSeed(pixel, parity, seed ^ 0x5bd1e995u), pair);
}

// The same point in [0, 1)^2, 24 bits each (exact in float, as rngNext).
vec2 sobolSample(uint index, uint seed) {
  return vec2(sobolBits(index, seed) >> 8u) * (1.0 / 16777216.0);
}

#endif
