// The GLSL shape table: each kind's module (primitives/shapes/) and the dispatch on
// Shape.kind (common/shape_kinds.h) to its intersection and normal; the C++ table is
// server/scene/shapes/shape_table.cpp (scene/shape.h describes the seam). A new kind adds its
// include and one case to each switch. Pure functions of their arguments: the geometry probe
// (probes/geometry_probe.comp) holds every kind against its double twin through them.
#ifndef SHAPE_TABLE_GLSL
#define SHAPE_TABLE_GLSL
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

#endif
