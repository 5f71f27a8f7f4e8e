// Confirms a sphere whose bounding box a chart ray entered: the intersection is solved in the
// model (exact for geodesic spheres in every geometry) and mapped back to the chart parameter
// the acceleration structure orders hits by.
#ifndef SPHERE_CANDIDATE_GLSL
#define SPHERE_CANDIDATE_GLSL
#if defined(HAS_SPHERES)

// (p, v): the ray in the cell's frame. On success s in [sMin, sMax] and t is the arc length.
bool sphereCandidate(SphereRef ref, vec4 p, vec4 v, float sMin, float sMax, out float s,
                     out float t) {
  Sphere sphere = spheres[ref.sphere];
  vec4 center = cellChartIsometry(ref.cell) * sphere.center;
#if defined(GEOMETRY_SPHERICAL)
  // The gnomonic chart parameter is periodic in t: only t <= tMax maps into [sMin, sMax].
  float tMax = sMax >= FAR ? FAR : distanceFromChartParameter(p, v, sMax);
#else
  // In E3 and H3 the chart parameter increases with t, so the s <= sMax below bounds t as
  // well: no arc length of sMax (an atanh per sphere and segment) to compute.
  float tMax = FAR;
#endif
  t = intersectGeodesicSphere(p, v, center, sphere.radius, 0.0, tMax);
  if (t <= 0.0) return false;
  s = chartParameter(p, v, t);
  return s >= sMin && s <= sMax;
}

#if defined(SPHERE_LIST)
// The nearest of the cell's spheres on the chart segment s in (0, sMax] (for a shadow ray any
// one), each tested as a traversal would confirm it: a cell with faces and a few spheres
// alone (server/render/prepare/pipeline_features.h sphere_list) needs no acceleration structure.
ChartHit nearestListedSphere(uint cell, vec4 p, vec4 v, float sMax, bool anyHit) {
  ChartHit best = noChartHit();
  Cell c = cellRecord(cell);
  for (uint i = c.sphere_begin; i < c.sphere_begin + c.sphere_count; ++i) {
    float s, t;
    if (!sphereCandidate(sphereRefs[i], p, v, 0.0, min(sMax, best.s), s, t)) continue;
    best = ChartHit(HIT_SPHERE, sphereRefs[i].sphere, s, t, vec2(0.0));
    if (anyHit) break;
  }
  return best;
}
#endif

#endif

#endif
