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

// Sobol's second dimension (primitive polynomial x + 1): direction numbers v_k = v_{k-1} ^
// (v_{k-1} >> 1) from v_0 = 2^31. The first dimension is the bit reversal of the index.
uint sobolSecond(uint index) {
  uint v = 0x80000000u, result = 0u;
  for (; index != 0u; index >>= 1u, v ^= v >> 1u)
    if ((index & 1u) != 0u) result ^= v;
  return result;
}

// Point `index` of the scrambled, shuffled sequence of `seed`, in 32-bit fixed point.
uvec2 sobolBits(uint index, uint seed) {
  uint shuffled = nestedUniformScramble(index, pcgHash(seed));
  return uvec2(nestedUniformScramble(bitfieldReverse(shuffled), pcgHash(seed ^ 0x9e3779b9u)),
               nestedUniformScramble(sobolSecond(shuffled), pcgHash(seed ^ 0x7f4a7c15u)));
}

// The same point in [0, 1)^2, 24 bits each (exact in float, as rngNext).
vec2 sobolSample(uint index, uint seed) {
  return vec2(sobolBits(index, seed) >> 8u) * (1.0 / 16777216.0);
}

#endif
