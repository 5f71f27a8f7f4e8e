// The scene's model geometry, chosen at compile time by GEOMETRY_HYPERBOLIC or
// GEOMETRY_SPHERICAL (default Euclidean), and the routines the three models share. Points and
// tangents are vec4 (server/geometry/model.h has the conventions); every routine is the float
// twin of the camelCase-named function there.
#ifndef GEOMETRY_MODEL_GLSL
#define GEOMETRY_MODEL_GLSL

#if defined(GEOMETRY_HYPERBOLIC)
#include "geometry/hyperbolic.glsl"
#elif defined(GEOMETRY_SPHERICAL)
#include "geometry/spherical.glsl"
#else
#include "geometry/euclidean.glsl"
#endif

#if defined(GEOMETRY_SPHERICAL)
// Within this (intrinsic) distance of S3's antipode a direction is round-off: every geodesic
// leads there.
const float ANTIPODE_TOLERANCE = 64.0 * 1.1920929e-7;
#endif

vec4 originPoint() { return vec4(0.0, 0.0, 0.0, 1.0); }

// v projected onto the tangent space at p and made unit; the zero vector if nothing is left.
vec4 normalizeTangent(vec4 p, vec4 v) {
  vec4 u = tangentPart(p, v);
  float n2 = modelInner(u, u);
  return n2 > 0.0 ? u / sqrt(n2) : vec4(0.0);
}

// Unit tangent at `from` of the shortest geodesic to `to`; zero when to == from or (S3) to is
// the antipode.
vec4 geodesicDirection(vec4 from, vec4 to) {
  vec4 u = tangentPart(from, to - from);  // |u| = sin d in S3
#if defined(GEOMETRY_SPHERICAL)
  if (dot(from, to) < 0.0 && dot(u, u) <= ANTIPODE_TOLERANCE * ANTIPODE_TOLERANCE)
    return vec4(0.0);
#endif
  return normalizeTangent(from, u);
}

mat4 translationFrom(vec4 q) { return translationTo(vec4(-q.xyz, q.w)); }

// The unit normal at q (pointing along +normal) of the geodesic plane {X : normal.X = delta}
// of the chart: the plane is the form-orthogonal complement of (normal, -K delta).
vec4 chartPlaneNormal(vec4 q, vec3 normal, float delta) {
  return normalizeTangent(q, vec4(normal, -GEOMETRY_CURVATURE * delta));
}

// The reflection in the geodesic plane {X : plane.xyz . chart(X) = plane.w} of the chart
// (unit normal), applied to a point or a tangent: X - 2 <X, m> m / <m, m> with m = (N, -K delta),
// which is x - 2 (N.x - delta) N in E3. Twin of reflection_in_chart_plane (model.h).
vec4 reflectInChartPlane(vec4 x, vec4 plane) {
  float offset = dot(plane.xyz, x.xyz) - plane.w * x.w;
  float norm2 = 1.0 + GEOMETRY_CURVATURE * plane.w * plane.w;
  return x - (2.0 * offset / norm2) * vec4(plane.xyz, -GEOMETRY_CURVATURE * plane.w);
}

// Outward unit normal at q of the geodesic sphere centred at `center`.
vec4 sphereNormal(vec4 center, vec4 q) { return -geodesicDirection(q, center); }

// The chart p.xyz / p.w (Klein in H3, gnomonic in S3): geodesics are straight lines in it.
vec3 chartPoint(vec4 p) { return p.xyz / p.w; }
vec4 liftChart(vec3 x) { return vec4(x, 1.0) / sqrt(1.0 + GEOMETRY_CURVATURE * dot(x, x)); }

// d/dt chartPoint(geodesicPoint(p, v, t)) at t = 0; the chart point at arc length t is
// chartPoint(p) + chartParameter(p, v, t) * chartDirection(p, v).
vec3 chartDirection(vec4 p, vec4 v) { return (v.xyz * p.w - p.xyz * v.w) / (p.w * p.w); }

// A secondary ray's origin: a step of surfaceOffsetLength(q) along the unit tangent n.
vec4 offsetFromSurface(vec4 q, vec4 n) {
  return normalizePoint(geodesicPoint(q, n, surfaceOffsetLength(q)));
}

#endif
