// Euclidean E3 in homogeneous coordinates: points (x, y, z, 1), tangents (x, y, z, 0),
// geodesics straight lines. The float twin of the E3 branches of server/geometry/model.cpp;
// include geometry/model.glsl, which picks a geometry and adds what the three share.
#ifndef GEOMETRY_EUCLIDEAN_GLSL
#define GEOMETRY_EUCLIDEAN_GLSL

const float GEOMETRY_CURVATURE = 0.0;

float modelInner(vec4 a, vec4 b) { return dot(a.xyz, b.xyz); }

// The part of v tangent at p.
vec4 tangentPart(vec4 p, vec4 v) { return vec4(v.xyz, 0.0); }

vec4 geodesicPoint(vec4 p, vec4 v, float t) { return p + t * v; }
vec4 geodesicTangent(vec4 p, vec4 v, float t) { return v; }
float geodesicDistance(vec4 a, vec4 b) { return length(b.xyz - a.xyz); }

mat4 translationTo(vec4 q) {
  mat4 g = mat4(1.0);
  g[3].xyz = q.xyz;
  return g;
}

// [R^T, -R^T x; 0, 1]
mat4 inverseIsometry(mat4 g) {
  mat3 rt = transpose(mat3(g));
  mat4 r = mat4(rt);
  r[3] = vec4(-(rt * g[3].xyz), 1.0);
  return r;
}

vec4 normalizePoint(vec4 p) { return vec4(p.xyz, 1.0); }

float chartParameter(vec4 p, vec4 v, float t) { return t; }
float distanceFromChartParameter(vec4 p, vec4 v, float s) { return s; }

// Closest approach (Ray Tracing Gems ch. 7): the discriminant comes from the vector l, so it
// stays accurate for far or grazing rays.
float intersectGeodesicSphere(vec4 p, vec4 v, vec4 center, float radius, float tMin,
                              float tMax) {
  vec3 f = p.xyz - center.xyz;
  float b = -dot(f, v.xyz);
  vec3 l = f + b * v.xyz;  // from the centre to the line's closest point
  float disc = radius * radius - dot(l, l);
  if (disc < 0.0) return -1.0;
  // sqrt(disc) takes b's sign so the sum never cancels; t0 t1 = |f|^2 - r^2.
  float q = b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(disc);
  float t0 = q != 0.0 ? (dot(f, f) - radius * radius) / q : 0.0;
  float t1 = q;
  if (t0 > t1) {
    float swap = t0;
    t0 = t1;
    t1 = swap;
  }
  if (t0 > tMin && t0 < tMax) return t0;
  if (t1 > tMin && t1 < tMax) return t1;
  return -1.0;
}

// 1e-4 plus 2^-15 of the largest |x|, |y|, |z| (256 ulps; w = 1 is exact).
float surfaceOffsetLength(vec4 q) {
  return 1e-4 + (1.0 / 32768.0) * max(abs(q.x), max(abs(q.y), abs(q.z)));
}

// A(d): the geodesic sphere of radius d has area 4 pi A(d) (point-light falloff 1 / A(d)).
float sphereAreaFactor(float d) { return d * d; }

// A(d(a, b)) without the distance (light-image weights, shaders/lights/emitters.glsl).
float areaFactorBetween(vec4 a, vec4 b) {
  vec3 d = b.xyz - a.xyz;
  return dot(d, d);
}

#endif
