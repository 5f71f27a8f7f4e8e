// The GLSL shape table: each kind's module (primitives/shapes/) and the dispatch on
// Shape.kind (common/shape_kinds.h) to its intersection and normal; the C++ table is
// server/scene/shapes/shape_table.cpp (scene/shape.h describes the seam). A new kind adds its
// include and one case to each switch.
#ifndef SHAPE_TABLE_GLSL
#define SHAPE_TABLE_GLSL
#if defined(HAS_SHAPES)
#include "common/shape_kinds.h"
#include "primitives/shapes/horosphere.glsl"

// The arc length of the geodesic (p, v)'s first crossing of the shape in (tMin, tMax), or
// FAR; a and b are the shape's vectors in the frame of (p, v).
float intersectShape(uint kind, vec4 a, vec4 b, float size, vec4 p, vec4 v, float tMin,
                     float tMax) {
  switch (kind) {
    case SHAPE_HOROSPHERE: return intersectHorosphere(p, v, a, tMin, tMax);
  }
  return FAR;
}

// The unit normal at the model point q on the shape, out of its solid side.
vec4 shapeNormal(Shape shape, vec4 q) {
  switch (shape.kind) {
    case SHAPE_HOROSPHERE: return horosphereNormal(shape.a, q);
  }
  return vec4(0.0);
}

// A shape may be unbounded (a horosphere), and H3's float geometry ends a few units out: a
// point at distance d from the chart's origin (the camera, or the cell's centre in a
// quotient) has Klein coordinates within 2 e^-2d of the unit sphere, which float soon cannot
// tell from it. Paths traced on from shape points up to d = 7 gave 2 NaN samples in 1.4e7, up
// to d = 6 2 in 5e7, up to d = 5 none in 5e7 (scenes/horospheres.json at 512x384, 256 spp).
// So a shape hit farther out than d = 5 (w > cosh 5) is seen and its emission counted, but no
// path goes on from it (Surface.horizon): the light it would reflect there is lost.
// E3 and S3 points have w <= 1.
const float SHAPE_HORIZON_W = 74.2099;  // cosh 5

// Confirms a shape whose bounding box a chart ray entered, as sphereCandidate does a sphere:
// (p, v) is the ray in the cell's frame; on success s in [sMin, sMax] and t is the arc length.
bool shapeCandidate(ShapeRef ref, vec4 p, vec4 v, float sMin, float sMax, out float s,
                    out float t) {
  Shape shape = shapes[ref.shape];
  mat4 P = cellChartIsometry(ref.cell);
  float tMax = sMax >= FAR ? FAR : distanceFromChartParameter(p, v, sMax);
  t = intersectShape(shape.kind, P * shape.a, P * shape.b, shape.size, p, v, 0.0, tMax);
  if (t >= FAR) return false;
  s = chartParameter(p, v, t);
  return s >= sMin && s <= sMax;
}

#endif
#endif
