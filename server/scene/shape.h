// The seam through which an analytic primitive enters the renderer. A kind of shape is one
// module on each side, listed once in each shape table under its number
// (shaders/common/shape_kinds.h):
// - C++: server/scene/shapes/<kind>.cpp defines a ShapeKind: its scene fields, its chart box,
//   and the double twin of its intersection and normal; scene/shapes/shape_table.cpp lists it.
// - GLSL: shaders/primitives/shapes/<kind>.glsl, its candidate test and normal;
//   shaders/primitives/shape_table.glsl dispatches to it.
// From there the loader, the packer (render/prepare/packed_scene.cpp), the acceleration
// builder and both back ends handle every shape alike: a box per shape per cell in the cell's
// acceleration structure, one hit group (entry/shape.*), one case of surfaceOf.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "geometry/chart_bounds.h"
#include "scene/json_path.h"
#include "scene/scene.h"

namespace geodesic {

struct ShapeKind {
  std::string_view type;                 // the scene file's object type, e.g. "horosphere"
  uint32_t id = 0;                       // SHAPE_* (shaders/common/shape_kinds.h)
  std::vector<std::string_view> fields;  // its fields, "type" and "material" included
  // Its parameters from a scene object (fields checked already), in a scene of geometry k;
  // a SceneError naming the field when they are invalid or the geometry has no such shape.
  ShapeParams (*read)(const JsonNode& object, GeometryKind k);
  // The chart box of the shape (its solid side included, when it bounds one) in a cell's
  // chart, its parameters carried into the cell's frame; nothing when it is unbounded there
  // (the packer then uses the cell's box).
  std::optional<ChartBox> (*chart_box)(GeometryKind k, const ShapeParams& in_frame);
  // The double twins of the GLSL module: the arc length of the first intersection of the
  // geodesic from p with unit tangent v in (t_min, t_max), or +infinity; the unit normal at a
  // point q of the surface, pointing out of its solid side.
  double (*intersect)(GeometryKind k, const ShapeParams& s, const Vec4& p, const Vec4& v,
                      double t_min, double t_max);
  Vec4 (*normal)(GeometryKind k, const ShapeParams& s, const Vec4& q);
};

// Every kind, in the order of their numbers.
const std::vector<const ShapeKind*>& shape_kinds();
// The kind with this scene type, or null.
const ShapeKind* find_shape_kind(std::string_view type);
// The kind with this number (ShapeKind::id, Shape::kind).
const ShapeKind& shape_kind(uint32_t id);

}  // namespace geodesic
