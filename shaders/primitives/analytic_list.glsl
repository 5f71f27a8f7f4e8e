// The analytic primitives a cell lists (SPHERE_LIST, SHAPE_LIST: both or neither where both
// kinds are present, server/render/prepare/pipeline_features.h): a chart segment tests them one
// by one, each as a traversal would confirm its box, and the acceleration structure, if
// traversed at all, holds the triangles alone.
#ifndef ANALYTIC_LIST_GLSL
#define ANALYTIC_LIST_GLSL
#include "primitives/shape_candidate.glsl"
#include "primitives/sphere_candidate.glsl"
#if defined(SPHERE_LIST) || defined(SHAPE_LIST)
#define ANALYTIC_LIST

#if defined(SPHERE_LIST)
#define LISTED_SPHERES(c) (c).sphere_count
#else
#define LISTED_SPHERES(c) 0u
#endif
#if defined(SHAPE_LIST)
#define LISTED_SHAPES(c) (c).shape_count
#else
#define LISTED_SHAPES(c) 0u
#endif

// The nearest of the cell's listed spheres and shapes (spheres first) on the chart segment s
// in (0, sMax] (for a shadow ray any one); (p, v) is the ray in the cell's frame.
ChartHit nearestListedAnalytic(uint cell, vec4 p, vec4 v, float sMax, bool anyHit) {
  ChartHit best = noChartHit();
  Cell c = cellRecord(cell);
  for (uint i = 0u; i < LISTED_SPHERES(c) + LISTED_SHAPES(c); ++i) {
    float s = FAR, t;
    uint kind = HIT_NONE, index = 0u;
    if (i < LISTED_SPHERES(c)) {
#if defined(SPHERE_LIST)
      SphereRef ref = sphereRefs[c.sphere_begin + i];
#if defined(LISTED_SPHERE_DATA)
      // A one-cell space's, baked in (pipeline_features.h listed_spheres): at the unrolled
      // loop's constant index, a test of constants.
      const vec4 listedSpheres[] = vec4[](LISTED_SPHERE_DATA);
      if (sphereAt(cellChartIsometry(cell) * listedSpheres[2u * i], listedSpheres[2u * i + 1u].x,
                   p, v, 0.0, min(sMax, best.s), s, t))
        kind = HIT_SPHERE;
#else
      if (sphereCandidate(ref, p, v, 0.0, min(sMax, best.s), s, t)) kind = HIT_SPHERE;
#endif
      index = ref.sphere;
#endif
    } else {
#if defined(SHAPE_LIST)
      ShapeRef ref = shapeRefs[c.shape_begin + i - LISTED_SPHERES(c)];
      if (shapeCandidate(ref, p, v, 0.0, min(sMax, best.s), s, t)) kind = HIT_SHAPE;
      index = ref.shape;
#endif
    }
    if (kind == HIT_NONE) continue;
    best = ChartHit(kind, index, s, t, vec2(0.0));
    if (anyHit) break;
  }
  return best;
}

#endif
#endif
