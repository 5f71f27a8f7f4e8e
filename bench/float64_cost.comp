#version 460
// The algebra of intersectGeodesicSphere (shaders/geometry/hyperbolic.glsl) in float or, with
// -DDOUBLE, in double, for bench/float64_cost.cpp. It stops at u = e^t of the first root:
// GLSL has no double log, exp, sin or cosh (GLSL.std.450 defines them for 16- and 32-bit
// floats only), so a double pipeline would have to bring its own.
layout(local_size_x = 64) in;

#ifdef DOUBLE
#define real double
#define real4 dvec4
#else
#define real float
#define real4 vec4
#endif

layout(std430, binding = 0) writeonly buffer Sums { float sums[]; };
layout(push_constant) uniform Push { uint count; uint repeats; } push;

real modelInner(real4 a, real4 b) { return dot(a.xyz, b.xyz) - a.w * b.w; }

real firstRoot(real4 p, real4 v, real4 c, real coshR, real sinhR) {
  real a = -modelInner(p, c), b = -modelInner(v, c);
  real4 n = c - a * p + b * v;
  real nn = max(modelInner(n, n), real(0));
  real disc = sinhR * sinhR - nn;
  if (disc < real(0)) return real(0);
  real e = coshR + sqrt(disc), product = real(1) + nn;
  real minus = b <= real(0) ? a - b : product / (a + b);
  return minus / e;
}

float unitFloat(uint x) {
  x = x * 747796405u + 2891336453u;
  x = ((x >> ((x >> 28u) + 4u)) ^ x) * 277803737u;
  return float((x >> 22u) ^ x) / 4294967296.0;
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  // A ray from near the origin and a sphere of radius 0.5 one to three away, made in float
  // from the invocation index (no zero coordinates for the compiler to fold); the loop nudges
  // the centre so nothing is hoisted out of it.
  vec3 u = vec3(unitFloat(3u * i), unitFloat(3u * i + 1u), unitFloat(3u * i + 2u)) - 0.5;
  vec3 axis = normalize(u + vec3(0.0, 0.0, 1e-3));
  float d = 1.0 + 2.0 * unitFloat(i ^ 0x9e3779b9u);
  vec3 x = 0.1 * u.yzx;
  real4 p = real4(x, sqrt(1.0 + dot(x, x)));
  real4 v = real4(normalize(axis + 0.1 * u), dot(axis, x));
  real4 c = real4(sinh(d) * axis, cosh(d));
  real coshR = real(cosh(0.5)), sinhR = real(sinh(0.5)), sum = real(0);
  for (uint k = 0u; k < push.repeats; ++k) {
    sum += firstRoot(p, v, c, coshR, sinhR);
    c.x += real(1e-4);
  }
  sums[i] = float(sum);
}
