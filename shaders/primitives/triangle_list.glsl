// The triangles of a cell that holds only a few, tested one by one instead of traversed: a
// ray query's or traceRay's setup costs more than a few dozen triangle tests
// (server/render/prepare/pipeline_features.h triangle_list).
#ifndef TRIANGLE_LIST_GLSL
#define TRIANGLE_LIST_GLSL
#if defined(TRIANGLE_LIST)
#include "geometry/triangle.glsl"

// The nearest of the cell's triangles on the chart segment o + s d, s in (0, sMax] (for a
// shadow ray any one), with the barycentrics a traversal reports. A triangle's corners are
// positions 3 t, 3 t + 1, 3 t + 2 (render/prepare/packed_scene.cpp: its indices are 0, 1, 2, ...).
ChartHit nearestListedTriangle(uint cell, vec3 o, vec3 d, float sMax, bool anyHit) {
  ChartHit best = noChartHit();
  Cell c = cellRecord(cell);
  // A segment that passes beside them all (most, where the triangles are a small object in a
  // large cell) tests none.
  if (!segmentMeetsBox(c.triangle_lo.xyz, c.triangle_hi.xyz, o, d, sMax)) return best;
  ShearedLine line = shearLine(d);
  for (uint t = c.triangle_begin; t < c.triangle_begin + c.triangle_count; ++t) {
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
