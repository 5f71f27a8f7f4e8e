// Confirms a shape whose bounding box a chart ray entered (as primitives/sphere_candidate.glsl
// does a sphere): the intersection is solved in the model by the shape table and mapped back
// to the chart parameter the acceleration structure orders hits by.
#ifndef SHAPE_CANDIDATE_GLSL
#define SHAPE_CANDIDATE_GLSL
#if defined(HAS_SHAPES)
#include "primitives/shape_table.glsl"

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
  t = intersectShape(shape.kind, P * shape.a, P * shape.b, shape.size, p, v, 0.0,
                     firstCrossingBound(p, v, sMax));
  if (t >= FAR) return false;
  s = chartParameter(p, v, t);
  return s >= sMin && s <= sMax;
}

#endif
#endif
