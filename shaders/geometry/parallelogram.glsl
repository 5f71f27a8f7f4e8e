// A chart line against a parallelogram that two listed triangles make: float twin of
// server/geometry/parallelogram.h (the comments there hold here), tested in place of the two
// watertight triangle tests (primitives/triangle_list.glsl).
#ifndef PARALLELOGRAM_GLSL
#define PARALLELOGRAM_GLSL

const float FAR_PARALLELOGRAM = 1e30;

// The s in (sMin, sMax] where o + s d meets the parallelogram of corners a, b = a + u,
// c = a + u + v (and a + v), or FAR_PARALLELOGRAM; alphaBeta: the point's coordinates along u
// and v. oScale: the largest |coordinate| of o.
float intersectChartParallelogram(vec3 o, vec3 d, float oScale, vec3 a, vec3 b, vec3 c,
                                  float sMin, float sMax, out vec2 alphaBeta) {
  alphaBeta = vec2(0.0);
  vec3 u = b - a, v = c - b, n = cross(u, v), ao = a - o;
  float denom = dot(n, d);
  if (denom == 0.0) return FAR_PARALLELOGRAM;
  float s = dot(n, ao) / denom;
  if (!(s > sMin && s <= sMax)) return FAR_PARALLELOGRAM;
  vec3 x = s * d - ao;
  float nn = dot(n, n);
  float alpha = dot(cross(x, v), n) / nn, beta = dot(cross(u, x), n) / nn;
  // How far outside [0, 1] each lies (<= 0 inside), against the margin m0 |v| / |n| and
  // m0 |u| / |n| (the lengths of the dual vectors), m0 = 2^-18 (1 + the largest |coordinate| of
  // o or a), compared squared.
  float outA = max(-alpha, alpha - 1.0), outB = max(-beta, beta - 1.0);
  float m0 = (1.0 / 262144.0) * (1.0 + max(oScale, max(max(abs(a.x), abs(a.y)), abs(a.z))));
  float m2 = m0 * m0;
  if ((outA > 0.0 && outA * outA * nn > m2 * dot(v, v)) ||
      (outB > 0.0 && outB * outB * nn > m2 * dot(u, u)))
    return FAR_PARALLELOGRAM;
  alphaBeta = vec2(alpha, beta);
  return s;
}

#endif
