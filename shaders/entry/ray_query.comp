#version 460
// Entry point 1: a compute kernel tracing with ray queries (fastest on lavapipe).
#extension GL_EXT_ray_query : require
#extension GL_GOOGLE_include_directive : require
#if defined(CULL_PRIMITIVES)
#extension GL_EXT_ray_flags_primitive_culling : require
#endif

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

#include "common/core.glsl"
#include "primitives/analytic_list.glsl"
#include "primitives/triangle_list.glsl"

// The closest (or, for shadows, any) hit along the chart segment o + s d, s in [0, sMax], in
// the given cell; (p, v) is the same ray in the cell's frame.
ChartHit traceChart(vec3 o, vec3 d, float sMax, uint cell, vec4 p, vec4 v, bool anyHit) {
  ChartHit best = noChartHit();
#if defined(ANALYTIC_LIST)
  // The cell's few spheres and shapes one by one; the acceleration structure holds its
  // triangles alone, which only a hit nearer than the nearest listed one's can matter.
  best = nearestListedAnalytic(cell, p, v, sMax, anyHit);
#if !defined(HAS_TRIANGLES)
  return best;
#endif
  if (anyHit && best.kind != HIT_NONE) return best;
  sMax = min(sMax, best.s);
#endif
#if defined(TRIANGLE_LIST)
  // And its few triangles one by one: nothing is traversed.
  ChartHit triangle = nearestListedTriangle(cell, o, d, sMax, anyHit);
  return triangle.kind != HIT_NONE ? triangle : best;
#elif defined(HAS_TRIANGLES) || defined(TRACED_BOXES)
  rayQueryEXT q;
  uint flags = CELL_OPACITY_FLAGS | (anyHit ? gl_RayFlagsTerminateOnFirstHitEXT : 0u) |
               PRIMITIVE_CULLING_FLAGS;
  rayQueryInitializeEXT(q, uScene, flags, cellMask(cell), o, 0.0, d, sMax);
  while (rayQueryProceedEXT(q)) {
    uint candidate = rayQueryGetIntersectionInstanceCustomIndexEXT(q, false) +
                     rayQueryGetIntersectionPrimitiveIndexEXT(q, false);
#if defined(SHARED_CELL_MASKS) && defined(HAS_TRIANGLES)
    if (rayQueryGetIntersectionTypeEXT(q, false) == gl_RayQueryCandidateIntersectionTriangleEXT) {
      if (triangles[candidate].cell == cell) rayQueryConfirmIntersectionEXT(q);
      continue;
    }
#endif
#if defined(TRACED_BOXES)
    if (rayQueryGetIntersectionTypeEXT(q, false) != gl_RayQueryCandidateIntersectionAABBEXT)
      continue;
    bool committed = rayQueryGetIntersectionTypeEXT(q, true) != gl_RayQueryCommittedIntersectionNoneEXT;
    float sLimit = committed ? rayQueryGetIntersectionTEXT(q, true) : sMax;
    float s, t;
    // A box's kind is its instance's hit record (render/device/acceleration.cpp).
    uint record = rayQueryGetIntersectionInstanceShaderBindingTableRecordOffsetEXT(q, false);
#if defined(HAS_SHAPES) && !defined(SHAPE_LIST)
    if (record == HIT_RECORD_SHAPES) {
      ShapeRef ref = shapeRefs[candidate];
#if defined(SHARED_CELL_MASKS)
      if (ref.cell != cell) continue;
#endif
      if (shapeCandidate(ref, p, v, 0.0, sLimit, s, t)) {
        rayQueryGenerateIntersectionEXT(q, s);
        best = ChartHit(HIT_SHAPE, ref.shape, s, t, vec2(0.0));
      }
      continue;
    }
#endif
#if defined(HAS_SPHERES) && !defined(SPHERE_LIST)
    SphereRef ref = sphereRefs[candidate];
#if defined(SHARED_CELL_MASKS)
    if (ref.cell != cell) continue;
#endif
    if (sphereCandidate(ref, p, v, 0.0, sLimit, s, t)) {
      rayQueryGenerateIntersectionEXT(q, s);
      best = ChartHit(HIT_SPHERE, ref.sphere, s, t, vec2(0.0));
    }
#endif
#endif
  }
#if defined(HAS_TRIANGLES)
  if (rayQueryGetIntersectionTypeEXT(q, true) == gl_RayQueryCommittedIntersectionTriangleEXT)
    return ChartHit(HIT_TRIANGLE,
                    rayQueryGetIntersectionInstanceCustomIndexEXT(q, true) +
                        rayQueryGetIntersectionPrimitiveIndexEXT(q, true),
                    rayQueryGetIntersectionTEXT(q, true), FAR,
                    rayQueryGetIntersectionBarycentricsEXT(q, true));
#endif
#endif
  // No triangle: the last generated box hit (the committed one), or the nearest listed
  // sphere or shape, or none.
  return best;
}

#include "integrator/integrator.glsl"

// Lavapipe hands each of its threads one contiguous run of a dispatch's workgroups (in x-fastest
// order), so with groups in image order one thread gets the top of a slice and another the
// bottom, and the first to finish idles while the other ends: a still view's 40 ms slices of a
// quotient space, whose pixels differ in cost many times over, kept the two cores 157 % busy.
// Workgroup i therefore takes tile b q + min(b, r) + i / K, b = i mod K (K = TILE_BLOCKS), for
// the n = q K + r tiles: the K blocks of the tiles are dealt round, so every run of consecutive
// workgroups (every thread's share) holds a part of each block, spread over the whole region. A
// bijection of [0, n): block b holds q + (b < r) tiles, the number of i < n with i mod K = b.
const uint TILE_BLOCKS = 16u;

uvec2 dealtTile() {
  uvec2 groups = gl_NumWorkGroups.xy;
  uint n = groups.x * groups.y;
  uint i = gl_WorkGroupID.y * groups.x + gl_WorkGroupID.x;
  uint q = n / TILE_BLOCKS, r = n % TILE_BLOCKS, b = i % TILE_BLOCKS;
  uint tile = b * q + min(b, r) + i / TILE_BLOCKS;
  return uvec2(tile % groups.x, tile / groups.x);
}

void main() { accumulatePixel(dealtTile() * gl_WorkGroupSize.xy + gl_LocalInvocationID.xy); }
