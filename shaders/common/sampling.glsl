// Direction sampling; mirrors server/geometry/sampling.h.
#ifndef SAMPLING_GLSL
#define SAMPLING_GLSL

const float PI = 3.14159265358979323846;

// Orthonormal basis around a unit vector (Duff et al. 2017, branchless).
void orthonormalBasis(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

// Cosine-weighted direction on the hemisphere around n: density cos(theta) / pi.
vec3 sampleCosineHemisphere(vec3 n, vec2 u) {
  float r = sqrt(u.x);
  float phi = 2.0 * PI * u.y;
  vec3 t, b;
  orthonormalBasis(n, t, b);
  return normalize(r * cos(phi) * t + r * sin(phi) * b + sqrt(max(0.0, 1.0 - u.x)) * n);
}

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

#endif
