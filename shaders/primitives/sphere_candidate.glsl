// Confirms a sphere whose bounding box a chart ray entered: the intersection is solved in the
// model (exact for geodesic spheres in every geometry) and mapped back to the chart parameter
// the acceleration structure orders hits by.
#ifndef SPHERE_CANDIDATE_GLSL
#define SPHERE_CANDIDATE_GLSL
#if defined(HAS_SPHERES)

// The sphere of centre `center` (in the cell's frame) and geodesic radius `radius` on the ray
// (p, v) in the cell's frame. On success s in [sMin, sMax] and t is the arc length.
bool sphereAt(vec4 center, float radius, vec4 p, vec4 v, float sMin, float sMax, out float s,
              out float t) {
  t = intersectGeodesicSphere(p, v, center, radius, 0.0, firstCrossingBound(p, v, sMax));
  if (t <= 0.0) return false;
  s = chartParameter(p, v, t);
  return s >= sMin && s <= sMax;
}
// The sphere `ref` likewise.
bool sphereCandidate(SphereRef ref, vec4 p, vec4 v, float sMin, float sMax, out float s,
                     out float t) {
  Sphere sphere = spheres[ref.sphere];
  return sphereAt(cellChartIsometry(ref.cell) * sphere.center, sphere.radius, p, v, sMin, sMax,
                  s, t);
}

#endif
#endif
