#include "render/prepare/packed_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/chart_bounds.h"
#include "render/prepare/triangle_list.h"
#include "render/prepare/tube_culling.h"
#include "scene/shape.h"

namespace geodesic {
namespace {

Float4 to_float4(const Vec3& v, double w = 0) {
  return {float(v.x), float(v.y), float(v.z), float(w)};
}
Float4 to_float4(const Vec4& v) { return {float(v.x), float(v.y), float(v.z), float(v.w)}; }

// Cells with faces are bounded in their chart; the box around their faces' planes, padded so
// that float rounding never clips geometry on the boundary. Cells without faces: everything.
ChartBox cell_box(const Cell& cell) {
  constexpr double kHuge = 1e30;
  ChartBox box{{-kHuge, -kHuge, -kHuge}, {kHuge, kHuge, kHuge}};
  // Axis-aligned faces (the tesseract atlas' cubes) bound the box directly.
  for (const CellFace& f : cell.faces) {
    const double pad = 1e-4 * (1 + std::abs(f.delta));
    for (int i = 0; i < 3; ++i) {
      if (std::abs(std::abs(f.normal[i]) - 1) > 1e-12) continue;
      if (f.normal[i] > 0) (i == 0 ? box.hi.x : i == 1 ? box.hi.y : box.hi.z) = f.delta + pad;
      else (i == 0 ? box.lo.x : i == 1 ? box.lo.y : box.lo.z) = -f.delta - pad;
    }
  }
  return box;
}

// A chart box as the acceleration structure's, padded outwards by a few float ulps of the
// coordinates so that rounding never clips what it bounds.
GpuAabb padded(const ChartBox& box) {
  const auto pad = [](double x) { return 1e-6 * (1 + std::abs(x)); };
  GpuAabb aabb{};
  for (int i = 0; i < 3; ++i) {
    aabb.min[i] = float(box.lo[i] - pad(box.lo[i]));
    aabb.max[i] = float(box.hi[i] + pad(box.hi[i]));
  }
  return aabb;
}

void pack_cell_triangles(const Scene& scene, const EmitterTable& emitting, const Cell& cell,
                         uint32_t cell_index, PackedScene& out) {
  const GeometryKind k = scene.geometry;
  const ChartBox box = cell_box(cell);
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    const bool smooth = k == GeometryKind::Euclidean && mesh.normals.size() == mesh.positions.size();
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      Vec3 chart[3];
      bool in_front = true;  // all three vertices on the chart's side (w > 0)
      for (int i = 0; i < 3; ++i) {
        const Vec4 q = cell.chart_isometry * model::exp_origin(k, mesh.positions[mesh.indices[t + i]]);
        in_front = in_front && q.w > 1e-6;
        chart[i] = q.xyz() / q.w;
      }
      if (!in_front) continue;
      ChartBox tri{chart[0], chart[0]};
      for (const Vec3& x : chart) {
        tri.lo = {std::min(tri.lo.x, x.x), std::min(tri.lo.y, x.y), std::min(tri.lo.z, x.z)};
        tri.hi = {std::max(tri.hi.x, x.x), std::max(tri.hi.y, x.y), std::max(tri.hi.z, x.z)};
      }
      if (!intersect(tri, box)) continue;
      const auto base = static_cast<uint32_t>(out.positions.size());
      for (int i = 0; i < 3; ++i) {
        out.positions.push_back(to_float4(chart[i], 1));
        out.normals.push_back(smooth ? to_float4(mesh.normals[mesh.indices[t + i]]) : Float4{});
        out.indices.push_back(base + i);
      }
      out.triangles.push_back(
          {mesh.material, smooth ? 1u : 0u, cell_index, emitting.triangle_emitter[m][t / 3]});
    }
  }
}

void pack_cell_spheres(const Scene& scene, const Cell& cell, uint32_t cell_index,
                       PackedScene& out) {
  const GeometryKind k = scene.geometry;
  const ChartBox box = cell_box(cell);
  for (uint32_t s = 0; s < scene.spheres.size(); ++s) {
    const Sphere& sphere = scene.spheres[s];
    const Vec4 centre = cell.chart_isometry * model::exp_origin(k, sphere.center);
    if (k == GeometryKind::Spherical && !cell.faces.empty()) {
      // Skip cells the ball cannot reach: the cube's corners are atan(sqrt 3) from its centre.
      const double to_cell = std::acos(std::clamp(centre.w, -1.0, 1.0));
      if (to_cell > sphere.radius + std::atan(std::sqrt(3.0)) + 1e-6) continue;
    }
    const auto bounds = sphere_chart_box(k, centre, sphere.radius);
    const auto clipped = bounds ? intersect(*bounds, box) : std::optional<ChartBox>(box);
    if (!clipped) continue;
    out.sphere_refs.push_back({s, cell_index});
    out.sphere_bounds.push_back(padded(*clipped));
  }
}

// The analytic shapes' boxes in the cell's chart (ShapeKind::chart_box, scene/shape.h),
// clipped to the cell's box.
void pack_cell_shapes(const Scene& scene, const Cell& cell, uint32_t cell_index,
                      PackedScene& out) {
  const ChartBox box = cell_box(cell);
  for (uint32_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& shape = scene.shapes[i];
    const ShapeParams in_frame{cell.chart_isometry * shape.params.a,
                               cell.chart_isometry * shape.params.b, shape.params.size};
    const auto bounds = shape_kind(shape.kind).chart_box(scene.geometry, in_frame);
    const auto clipped = bounds ? intersect(*bounds, box) : std::optional<ChartBox>(box);
    if (!clipped) continue;
    out.shape_refs.push_back({i, cell_index});
    out.shape_bounds.push_back(padded(*clipped));
  }
}

// The edge tubes in the cell's chart: their ends mapped there, the chart radius kept (exact for
// a domain charted about the origin in one cell, as every bundled quotient is; a domain charted
// in pieces bends a tube's surface where it changes chart by a fraction of its radius). Sorted
// by the two faces that hold the axis, each first face given its offset and the set of second
// faces, so that a segment finds the tube on a pair of near faces at once; a tube without two
// such faces, or on a pair that already has one, goes last, always tested
// (render/prepare/tube_culling.h). Fills the cell's tube fields.
void pack_cell_tubes(const Scene& scene, const Cell& cell, GpuCell& packed, PackedScene& out) {
  const GeometryKind k = scene.geometry;
  std::vector<GpuTube> tubes;
  for (const EdgeTube& tube : scene.tubes) {
    const Vec4 a = cell.chart_isometry * model::lift(k, tube.a);
    const Vec4 b = cell.chart_isometry * model::lift(k, tube.b);
    if (a.w <= 1e-6 || b.w <= 1e-6) continue;  // not on the chart's side
    const auto [face_a, face_b] = faces_holding(cell, a.xyz() / a.w, b.xyz() / b.w);
    tubes.push_back({to_float4(a.xyz() / a.w, tube.radius), to_float4(b.xyz() / b.w),
                     tube.material, face_a, face_b, 0});
    packed.tube_reach = std::max(packed.tube_reach, float(tube.radius));
  }
  std::stable_sort(tubes.begin(), tubes.end(), [](const GpuTube& x, const GpuTube& y) {
    return std::pair(x.face_a, x.face_b) < std::pair(y.face_a, y.face_b);
  });
  // Past the first tube on a pair of faces (sorted together), the others are always tested.
  for (size_t first = 0, i = 1; i < tubes.size(); ++i) {
    if (tubes[i].face_a == kAlwaysTest) break;  // sorted last
    if (tubes[i].face_a != tubes[first].face_a || tubes[i].face_b != tubes[first].face_b)
      first = i;
    else
      tubes[i].face_a = tubes[i].face_b = kAlwaysTest;
  }
  std::stable_partition(tubes.begin(), tubes.end(),
                        [](const GpuTube& t) { return t.face_a != kAlwaysTest; });
  if (tubes.size() > 0xFFFF) throw SceneError("more than 65535 edge tubes in one cell");
  packed.tube_begin = uint32_t(out.tubes.size());
  packed.tube_count = uint32_t(tubes.size());
  packed.always_begin = packed.tube_count;
  for (uint32_t i = 0; i < tubes.size(); ++i) {
    if (tubes[i].face_a == kAlwaysTest) {
      packed.always_begin = std::min(packed.always_begin, i);
      continue;
    }
    GpuCellFace& face = out.faces[cell.face_begin + tubes[i].face_a];
    if (face.tube_partners == 0) face.tubes = i;
    face.tube_partners |= 1u << tubes[i].face_b;
  }
  out.tubes.insert(out.tubes.end(), tubes.begin(), tubes.end());
}

// A cell's triangles (from `first`) and its sphere refs (from `first_ref`) in the index-split
// order of their chart boxes (render/prepare/spatial_order.h). Triangle vertices are not shared, so
// positions and normals move with their triangle and the indices stay 0, 1, 2, ...
void order_spatially(uint32_t first, uint32_t first_ref, PackedScene& out) {
  const auto permute = [](auto& items, size_t begin, size_t stride,
                          const std::vector<uint32_t>& order) {
    const std::vector range(items.begin() + long(begin), items.end());
    for (size_t k = 0; k < order.size(); ++k)
      for (size_t i = 0; i < stride; ++i)
        items[begin + k * stride + i] = range[order[k] * stride + i];
  };
  std::vector<PrimitiveBox> boxes = triangle_boxes(out, first);
  std::vector<uint32_t> order = index_split_order(boxes);
  permute(out.triangles, first, 1, order);
  permute(out.positions, 3 * size_t(first), 3, order);
  permute(out.normals, 3 * size_t(first), 3, order);
  boxes.clear();
  for (size_t r = first_ref; r < out.sphere_bounds.size(); ++r) {
    const GpuAabb& b = out.sphere_bounds[r];
    boxes.push_back({Vec3{b.min[0], b.min[1], b.min[2]}, Vec3{b.max[0], b.max[1], b.max[2]}});
  }
  order = index_split_order(boxes);
  permute(out.sphere_refs, first_ref, 1, order);
  permute(out.sphere_bounds, first_ref, 1, order);
}

// The chart boxes around what the cell's segments trace (its triangles, sphere refs and shape
// refs: the ranges in `g`, the triangles last in `out`) and around its triangles alone, padded
// by 1e-4 of the coordinates beyond the boxes' own padding, so that the shader's float slab
// test never turns away a segment that meets one of them. Empty (lo > hi) when there is none.
void set_content_boxes(const PackedScene& out, const CellGeometry& g, GpuCell& packed) {
  ChartBox box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  const auto add = [&box](const Vec3& lo, const Vec3& hi) {
    box.lo = {std::min(box.lo.x, lo.x), std::min(box.lo.y, lo.y), std::min(box.lo.z, lo.z)};
    box.hi = {std::max(box.hi.x, hi.x), std::max(box.hi.y, hi.y), std::max(box.hi.z, hi.z)};
  };
  const auto add_aabbs = [&add](const std::vector<GpuAabb>& boxes, uint32_t first, uint32_t n) {
    for (uint32_t i = first; i < first + n; ++i)
      add({boxes[i].min[0], boxes[i].min[1], boxes[i].min[2]},
          {boxes[i].max[0], boxes[i].max[1], boxes[i].max[2]});
  };
  const auto write = [&box](std::array<float, 4>& lo, std::array<float, 4>& hi) {
    const auto pad = [](double x) { return 1e-4 * (1 + std::abs(x)); };
    for (int i = 0; i < 3; ++i) {
      const bool empty = box.lo[i] > box.hi[i];
      lo[i] = empty ? 1.0f : float(box.lo[i] - pad(box.lo[i]));
      hi[i] = empty ? -1.0f : float(box.hi[i] + pad(box.hi[i]));
    }
  };
  for (const PrimitiveBox& t : triangle_boxes(out, g.first_triangle)) add(t.lo, t.hi);
  write(packed.triangle_lo, packed.triangle_hi);
  add_aabbs(out.sphere_bounds, g.first_sphere_ref, g.sphere_ref_count);
  add_aabbs(out.shape_bounds, g.first_shape_ref, g.shape_ref_count);
  write(packed.content_lo, packed.content_hi);
}

}  // namespace

std::vector<PrimitiveBox> triangle_boxes(const PackedScene& packed, size_t first) {
  std::vector<PrimitiveBox> boxes;
  for (size_t t = first; t < packed.triangles.size(); ++t) {
    PrimitiveBox box{Vec3{INFINITY, INFINITY, INFINITY}, Vec3{-INFINITY, -INFINITY, -INFINITY}};
    for (int i = 0; i < 3; ++i) {
      const Float4& x = packed.positions[3 * t + i];
      box.lo = {std::min(box.lo.x, double(x[0])), std::min(box.lo.y, double(x[1])), std::min(box.lo.z, double(x[2]))};
      box.hi = {std::max(box.hi.x, double(x[0])), std::max(box.hi.y, double(x[1])), std::max(box.hi.z, double(x[2]))};
    }
    boxes.push_back(box);
  }
  return boxes;
}

PackedScene pack_scene(const Scene& scene) {
  const GeometryKind k = scene.geometry;
  PackedScene out;
  for (const Material& m : scene.materials)
    out.materials.push_back({to_float4(m.ambient), to_float4(m.diffuse),
                             to_float4(m.specular, m.shininess), to_float4(m.mirror),
                             to_float4(m.transmission, m.ior), to_float4(m.emission)});
  const EmitterTable emitting = build_emitters(scene);
  out.emitters = emitting.emitters;
  out.light_images = emitting.images;
  out.light_cutoff = emitting.cutoff;
  out.every_light_image = emitting.every_image;
  for (size_t s = 0; s < scene.spheres.size(); ++s)
    out.spheres.push_back({to_float4(model::exp_origin(k, scene.spheres[s].center)),
                           float(scene.spheres[s].radius), scene.spheres[s].material,
                           emitting.sphere_emitter[s], 0});
  for (size_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& shape = scene.shapes[i];
    out.shapes.push_back({to_float4(shape.params.a), to_float4(shape.params.b),
                          float(shape.params.size), shape.kind, shape.material,
                          emitting.shape_emitter[i]});
  }
  for (const PointLight& l : scene.lights)
    out.lights.push_back({to_float4(model::exp_origin(k, l.position)), to_float4(l.intensity)});

  const std::vector<Cell> cells = build_cells(scene);
  for (uint32_t c = 0; c < cells.size(); ++c) {
    const Cell& cell = cells[c];
    for (const CellFace& f : cell.faces)
      out.faces.push_back({to_float4(f.normal, f.delta), f.pairing.to_glsl(),
                           uint32_t(f.target_cell), uint32_t(f.partner), uint32_t(f.internal), 0});
    GpuCell packed{};
    packed.chart_isometry = cell.chart_isometry.to_glsl();
    packed.face_begin = uint32_t(cell.face_begin);
    packed.face_count = uint32_t(cell.faces.size());
    pack_cell_tubes(scene, cell, packed, out);
    CellGeometry g;
    g.first_triangle = uint32_t(out.triangles.size());
    pack_cell_triangles(scene, emitting, cell, c, out);
    g.triangle_count = uint32_t(out.triangles.size()) - g.first_triangle;
    g.first_sphere_ref = uint32_t(out.sphere_refs.size());
    pack_cell_spheres(scene, cell, c, out);
    g.sphere_ref_count = uint32_t(out.sphere_refs.size()) - g.first_sphere_ref;
    g.first_shape_ref = uint32_t(out.shape_refs.size());
    pack_cell_shapes(scene, cell, c, out);
    g.shape_ref_count = uint32_t(out.shape_refs.size()) - g.first_shape_ref;
    order_spatially(g.first_triangle, g.first_sphere_ref, out);
    set_content_boxes(out, g, packed);
    packed.listed_begin = uint32_t(out.listed.size());
    packed.listed_pairs = list_cell_triangles(g.first_triangle, g.triangle_count, out);
    packed.listed_count = uint32_t(out.listed.size()) - packed.listed_begin;
    list_hull_first(k == GeometryKind::Euclidean, cell, g.first_triangle, g.triangle_count,
                    g.shape_ref_count > 0, out, packed);
    packed.sphere_begin = g.first_sphere_ref;
    packed.sphere_count = g.sphere_ref_count;
    packed.shape_begin = g.first_shape_ref;
    packed.shape_count = g.shape_ref_count;
    out.cells.push_back(packed);
    out.cell_geometry.push_back(g);
  }
  const CameraPlacement camera = place_camera(k, cells, scene.camera.pose);
  out.camera_pose = camera.pose;
  out.camera_cell = camera.cell;
  return out;
}

}  // namespace geodesic
