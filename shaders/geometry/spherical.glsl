// Spherical S3: the unit sphere of R^4, tangents p.v = 0. The float twin of the S3 branches of
// server/geometry/model.cpp; include geometry/model.glsl, which picks a geometry and adds
// what the three share.
#ifndef GEOMETRY_SPHERICAL_GLSL
#define GEOMETRY_SPHERICAL_GLSL

const float GEOMETRY_CURVATURE = 1.0;
const float QUARTER_PI = 0.78539816339744830962;
const float HALF_PI = 1.57079632679489661923;
const float TWO_PI = 6.28318530717958647692;

// atan2 to a few ulps: Vulkan allows atan 4096 ulps, and lavapipe's is off by ~350 (4e-6 in
// a distance). Cephes' atanf on [0, tan(pi/8)] after reducing |y|/|x| to [0, 1].
float atan2Accurate(float y, float x) {
  float ax = abs(x), ay = abs(y), big = max(ax, ay);
  float a = big > 0.0 ? min(ax, ay) / big : 0.0, r = 0.0;
  if (a > 0.41421356) {  // atan a = pi/4 + atan((a - 1) / (a + 1))
    r = QUARTER_PI;
    a = (a - 1.0) / (a + 1.0);
  }
  float z = a * a;
  r += (((8.05374449538e-2 * z - 1.38776856032e-1) * z + 1.99777106478e-1) * z -
        3.33329491539e-1) * z * a + a;
  if (ay > ax) r = HALF_PI - r;
  if (x < 0.0) r = 2.0 * HALF_PI - r;
  return y < 0.0 ? -r : r;
}

float modelInner(vec4 a, vec4 b) { return dot(a, b); }

// The part of v tangent at p.
vec4 tangentPart(vec4 p, vec4 v) { return v - dot(p, v) * p; }

vec4 geodesicPoint(vec4 p, vec4 v, float t) { return cos(t) * p + sin(t) * v; }
vec4 geodesicTangent(vec4 p, vec4 v, float t) { return -sin(t) * p + cos(t) * v; }

// |b-a| = 2 sin(d/2), |b+a| = 2 cos(d/2): accurate for every d in [0, pi].
float geodesicDistance(vec4 a, vec4 b) { return 2.0 * atan2Accurate(length(b - a), length(a + b)); }

// The rotation [I - x x^T / (1 + w), x; -x^T, w] carrying the origin to q = (x, w). On the
// sphere x x^T / (1 + w) = (1 - w) x^ x^T, the form used for w < 0 where 1 + w cancels; at
// the antipode (x = 0) no rotation is singled out and x^ = e_x gives the half-turn in the
// xw plane.
mat4 translationTo(vec4 q) {
  vec3 axis = q.xyz;
  float scale = 1.0 / (1.0 + q.w);
  if (q.w < 0.0) {
    float s = length(q.xyz);
    axis = s > 0.0 ? q.xyz / s : vec3(1.0, 0.0, 0.0);
    scale = 1.0 - q.w;
  }
  mat3 m = mat3(1.0) - scale * outerProduct(axis, axis);
  return mat4(vec4(m[0], -q.x), vec4(m[1], -q.y), vec4(m[2], -q.z), q);
}

mat4 inverseIsometry(mat4 g) { return transpose(g); }

vec4 normalizePoint(vec4 p) { return p / sqrt(dot(p, p)); }

float chartParameter(vec4 p, vec4 v, float t) {
  return p.w * sin(t) / (p.w * cos(t) + v.w * sin(t));
}

// (s |p.w|, |p.w| - s v.w sign p.w) is a positive multiple of (sin t, cos t) while the
// geodesic stays in p's hemisphere, so atan2 goes on past pi/2 there.
float distanceFromChartParameter(vec4 p, vec4 v, float s) {
  float w = abs(p.w);
  return atan2Accurate(s * w, w - s * (p.w < 0.0 ? -v.w : v.w));
}

// The smallest of t + 2 pi n (n integer) above tMin: the geodesic comes round every 2 pi.
float nextTurnAfter(float t, float tMin) {
  float shifted = t + TWO_PI * ceil((tMin - t) / TWO_PI);
  return shifted <= tMin ? shifted + TWO_PI : shifted;
}

// A cos t + B sin t = cos r with A = p.c, B = v.c, i.e. rho cos(t - phi) = cos r. With
// c = A p + B v + n (n perpendicular to p and v, |n| = sin(distance from c to the geodesic)),
// rho^2 - cos^2 r = sin^2 r - |n|^2 comes from n without cancellation, and
// t = phi -+ atan2(sqrt(that), cos r).
float intersectGeodesicSphere(vec4 p, vec4 v, vec4 center, float radius, float tMin,
                              float tMax) {
  float a = dot(p, center), b = dot(v, center);
  vec4 n = center - a * p - b * v;
  float sinR = sin(radius);
  float disc = sinR * sinR - dot(n, n);
  if (disc < 0.0) return -1.0;
  float phi = atan2Accurate(b, a), spread = atan2Accurate(sqrt(disc), cos(radius));
  float t = min(nextTurnAfter(phi - spread, tMin), nextTurnAfter(phi + spread, tMin));
  return t < tMax ? t : -1.0;
}

// 1e-4 plus 2^-15 (256 ulps) of the largest coordinate (at most 1).
float surfaceOffsetLength(vec4 q) {
  return 1e-4 + (1.0 / 32768.0) * max(max(abs(q.x), abs(q.y)), max(abs(q.z), abs(q.w)));
}

// A(d): the geodesic sphere of radius d has area 4 pi A(d) (point-light falloff 1 / A(d)).
float sphereAreaFactor(float d) { return sin(d) * sin(d); }

// A(d(a, b)) without the distance: sin^2 d = 4 sin^2(d/2) cos^2(d/2) = |b-a|^2 |b+a|^2 / 4,
// exact for every d in [0, pi] as geodesicDistance is.
float areaFactorBetween(vec4 a, vec4 b) {
  vec4 d = b - a, s = b + a;
  return 0.25 * dot(d, d) * dot(s, s);
}

#endif
