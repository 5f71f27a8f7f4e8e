// The triangles of a cell that holds only a few, tested one by one instead of traversed: a
// ray query's or traceRay's setup costs more than a few dozen triangle tests
// (server/render/prepare/pipeline_features.h triangle_list). Two that make a parallelogram are
// tested as one (server/render/prepare/triangle_list.h).
#ifndef TRIANGLE_LIST_GLSL
#define TRIANGLE_LIST_GLSL
#if defined(TRIANGLE_LIST)
#include "geometry/parallelogram.glsl"
#include "geometry/triangle.glsl"

// The nearest of the cell's listed primitives on the chart segment o + s d, s in (0, sMax]
// (for a shadow ray any one), as the triangle that holds it with the barycentrics a traversal
// reports. A triangle's corners are positions 3 t, 3 t + 1, 3 t + 2
// (render/prepare/packed_scene.cpp: its indices are 0, 1, 2, ...).
ChartHit nearestListedTriangle(uint cell, vec3 o, vec3 d, float sMax, bool anyHit) {
  ChartHit best = noChartHit();
  Cell c = cellRecord(cell);
  // A segment that passes beside them all (most, where the triangles are a small object in a
  // large cell) tests none.
  if (!segmentMeetsBox(c.triangle_lo.xyz, c.triangle_hi.xyz, o, d, sMax)) return best;
  // The cell's parallelograms (render/prepare/triangle_list.h), then its lone triangles; a
  // shadow segment skips those on the scene's hull, which it cannot cross (listed first).
  float oScale = max(max(abs(o.x), abs(o.y)), abs(o.z));
  uint pairsEnd = c.listed_begin + c.listed_pairs, end = c.listed_begin + c.listed_count;
  uint loneBegin = pairsEnd + (anyHit ? c.listed_hull_lone : 0u);
  for (uint i = c.listed_begin + (anyHit ? c.listed_hull_pairs : 0u); i < pairsEnd; ++i) {
    uint t = listed[i].triangle;
    vec2 ab;
    float s = intersectChartParallelogram(o, d, oScale, positions[3u * t].xyz,
                                          positions[3u * t + 1u].xyz, positions[3u * t + 2u].xyz,
                                          0.0, min(sMax, best.s), ab);
    if (s == FAR_PARALLELOGRAM) continue;
    // The half that holds it (server/geometry/parallelogram.h paired_triangle_hit).
    best = ab.y <= ab.x ? ChartHit(HIT_TRIANGLE, t, s, FAR, vec2(ab.x - ab.y, ab.y))
                        : ChartHit(HIT_TRIANGLE, listed[i].second, s, FAR,
                                   vec2(ab.x, ab.y - ab.x));
    if (anyHit) return best;
  }
  if (loneBegin == end) return best;
  ShearedLine line = shearLine(d);
  for (uint i = loneBegin; i < end; ++i) {
    uint t = listed[i].triangle;
    vec2 uv;
    float s = intersectChartTriangle(line, o, positions[3u * t].xyz, positions[3u * t + 1u].xyz,
                                     positions[3u * t + 2u].xyz, 0.0, min(sMax, best.s), uv);
    if (s == FAR_TRIANGLE) continue;
    best = ChartHit(HIT_TRIANGLE, t, s, FAR, uv);
    if (anyHit) break;
  }
  return best;
}

#endif
#endif
