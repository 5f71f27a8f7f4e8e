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

// The unit vector at polar angle acos(cosTheta), azimuth phi around the unit axis.
vec3 aroundAxis(vec3 axis, float cosTheta, float phi) {
  float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
  vec3 t, b;
  orthonormalBasis(axis, t, b);
  return normalize(sinTheta * cos(phi) * t + sinTheta * sin(phi) * b + cosTheta * axis);
}

// Phong lobe around r: density (e + 1) / (2 pi) cos^e(alpha).
vec3 samplePhongLobe(vec3 r, float exponent, vec2 u) {
  return aroundAxis(r, pow(1.0 - u.x, 1.0 / (exponent + 1.0)), 2.0 * PI * u.y);
}
float phongLobePdf(vec3 r, float exponent, vec3 w) {
  float c = dot(r, w);
  return c <= 0.0 ? 0.0 : (exponent + 1.0) / (2.0 * PI) * pow(c, exponent);
}

// Uniform direction within acos(cosMax) of the axis: density 1 / (2 pi (1 - cosMax)).
vec3 sampleUniformCone(vec3 axis, float cosMax, vec2 u) {
  return aroundAxis(axis, 1.0 - u.x * (1.0 - cosMax), 2.0 * PI * u.y);
}

// Uniform point of a triangle: barycentrics of its second and third corners.
vec2 sampleUniformTriangle(vec2 u) {
  float s = sqrt(u.x);
  return vec2(1.0 - s, u.y * s);
}

// Unpolarised Fresnel reflectance for cosI > 0 and eta = n_transmitted / n_incident.
float fresnelDielectric(float cosI, float eta) {
  float sin2T = (1.0 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.0) return 1.0;
  float cosT = sqrt(1.0 - sin2T);
  float parallel = (eta * cosI - cosT) / (eta * cosI + cosT);
  float perpendicular = (cosI - eta * cosT) / (cosI + eta * cosT);
  return 0.5 * (parallel * parallel + perpendicular * perpendicular);
}

// Veach's power heuristic.
float powerHeuristic(float a, float b) {
  if (a <= 0.0) return 0.0;
  if (isinf(a)) return 1.0;
  return a * a / (a * a + b * b);
}

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

#endif
