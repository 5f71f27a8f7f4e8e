// Hyperbolic H3 on the hyperboloid <p,p> = -1, w > 0 of R^{3,1}, tangents <p,v> = 0. The
// float twin of the H3 branches of server/geometry/model.cpp; include geometry/model.glsl,
// which picks a geometry and adds what the three share.
#ifndef GEOMETRY_HYPERBOLIC_GLSL
#define GEOMETRY_HYPERBOLIC_GLSL

const float GEOMETRY_CURVATURE = -1.0;

float modelInner(vec4 a, vec4 b) { return dot(a.xyz, b.xyz) - a.w * b.w; }

// sinh, tanh, asinh and atanh to a few ulps near 0, where the driver's exp/log forms cancel
// (sinh from e^x - e^-x keeps 3 digits at 1e-4): Taylor series there, the built-ins (tanh:
// one exp) beyond.
float sinhSeries(float x) {  // |x| < 0.5
  float x2 = x * x;
  // Coefficients folded at compile time: SIMD lanes run both sides of the select, and x2 / 6,
  // x2 / 20, ... were four divisions on every call (3-8 % of an H3 quotient's time).
  return x *
         (1.0 + x2 * (1.0 / 6.0 + x2 * (1.0 / 120.0 + x2 * (1.0 / 5040.0 + x2 * (1.0 / 362880.0)))));
}
float sinhStable(float x) { return abs(x) < 0.5 ? sinhSeries(x) : sinh(x); }
// tanh |x| = (1 - e) / (1 + e) from e = e^-2|x| (which cannot overflow) beyond 0.5, and
// sinh / cosh = sinh / sqrt(1 + sinh^2) from the series below: one exp where the built-ins'
// sinh, cosh and tanh took four, and closer to the double twin (docs/quotient-speed.md; no faster).
float tanhStable(float x) {
  float small = sinhSeries(x), e = exp(-2.0 * abs(x));
  float large = (1.0 - e) / (1.0 + e);
  return abs(x) < 0.5 ? small / sqrt(1.0 + small * small) : (x < 0.0 ? -large : large);
}
float asinhStable(float x) {
  float x2 = x * x;
  float series =
      1.0 - x2 * (1.0 / 6.0 - x2 * (3.0 / 40.0 - x2 * (5.0 / 112.0 - x2 * (35.0 / 1152.0))));
  return abs(x) < 0.25 ? x * series : asinh(x);
}
float atanhStable(float x) {
  float x2 = x * x;
  float series = 1.0 + x2 * (1.0 / 3.0 + x2 * (1.0 / 5.0 + x2 * (1.0 / 7.0 + x2 * (1.0 / 9.0 +
                                                                             x2 * (1.0 / 11.0)))));
  return abs(x) < 0.25 ? x * series : atanh(x);
}

// The part of v tangent at p.
vec4 tangentPart(vec4 p, vec4 v) { return v + modelInner(p, v) * p; }

vec4 geodesicPoint(vec4 p, vec4 v, float t) { return cosh(t) * p + sinhStable(t) * v; }
vec4 geodesicTangent(vec4 p, vec4 v, float t) { return sinhStable(t) * p + cosh(t) * v; }

// 4 sinh^2(d/2) for d = d(a, b): <b-a, b-a> keeps close points exact but cancels for far
// ones, where 2 (cosh d - 1) from -<a, b> = cosh d is the accurate one.
float chordSquared(vec4 a, vec4 b) {
  float coshD = -modelInner(a, b);
  vec4 d = b - a;
  return coshD > 2.0 ? 2.0 * (coshD - 1.0) : max(modelInner(d, d), 0.0);
}
float geodesicDistance(vec4 a, vec4 b) { return 2.0 * asinhStable(0.5 * sqrt(chordSquared(a, b))); }

// The boost [I + x x^T / (1 + w), x; x^T, w] carrying the origin to q = (x, w).
mat4 translationTo(vec4 q) {
  mat3 m = mat3(1.0) + outerProduct(q.xyz, q.xyz) / (1.0 + q.w);
  return mat4(vec4(m[0], q.x), vec4(m[1], q.y), vec4(m[2], q.z), q);
}

// J g^T J, J = diag(1, 1, 1, -1).
mat4 inverseIsometry(mat4 g) {
  mat4 r = transpose(g);
  r[3].xyz = -r[3].xyz;
  r[0].w = -r[0].w;
  r[1].w = -r[1].w;
  r[2].w = -r[2].w;
  return r;
}

// w from xyz: -<p,p> = w^2 - |x|^2 cancels far out, so scaling by it would not do.
vec4 normalizePoint(vec4 p) { return vec4(p.xyz, sqrt(1.0 + dot(p.xyz, p.xyz))); }

// p.w tanh t / (p.w + v.w tanh t): tanh keeps large t finite.
float chartParameter(vec4 p, vec4 v, float t) {
  float tanhT = tanhStable(t);
  return p.w * tanhT / (p.w + v.w * tanhT);
}

float distanceFromChartParameter(vec4 p, vec4 v, float s) {
  return atanhStable(s * p.w / (p.w - s * v.w));
}

// A cosh t + B sinh t = cosh r with A = -<p,c>, B = -<v,c>: (A+B) u^2 - 2 cosh r u + (A-B) = 0
// in u = e^t. c = A p - B v + n, n perpendicular to p and v, |n| = sinh(distance from c to
// the geodesic): the discriminant sinh^2 r - |n|^2 comes from n without cancellation, and of
// A -+ B (both >= e^-d) the one that does not cancel gives the other by (A-B)(A+B) = 1 + |n|^2.
float intersectGeodesicSphere(vec4 p, vec4 v, vec4 center, float radius, float tMin,
                              float tMax) {
  float a = -modelInner(p, center), b = -modelInner(v, center);
  vec4 n = center - a * p + b * v;
  float nn = max(modelInner(n, n), 0.0);
  float sinhR = sinhStable(radius);
  float disc = sinhR * sinhR - nn;
  if (disc < 0.0) return -1.0;
  float e = cosh(radius) + sqrt(disc), product = 1.0 + nn;
  float minus = b <= 0.0 ? a - b : product / (a + b);
  float plus = b <= 0.0 ? product / (a - b) : a + b;
  float t0 = log(minus / e), t1 = log(e / plus);
  if (t0 > tMin && t0 < tMax) return t0;
  if (t1 > tMin && t1 < tMax) return t1;
  return -1.0;
}

// 1e-4 plus 2^-15 (256 ulps) of the largest coordinate, w: a float point here is only known
// to about an ulp of w in the directions across the radius from the origin.
float surfaceOffsetLength(vec4 q) {
  return 1e-4 + (1.0 / 32768.0) * max(max(abs(q.x), abs(q.y)), max(abs(q.z), abs(q.w)));
}

// A(d): the geodesic sphere of radius d has area 4 pi A(d) (point-light falloff 1 / A(d)).
float sphereAreaFactor(float d) { return sinhStable(d) * sinhStable(d); }

// A(d(a, b)) without the distance: with q = 4 sinh^2(d/2) (chordSquared),
// sinh^2 d = 4 sinh^2(d/2) cosh^2(d/2) = q (1 + q / 4).
float areaFactorBetween(vec4 a, vec4 b) {
  float q = chordSquared(a, b);
  return q * (1.0 + 0.25 * q);
}

#endif
