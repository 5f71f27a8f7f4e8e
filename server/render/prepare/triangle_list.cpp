#include "render/prepare/triangle_list.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "geometry/vec.h"
#include "render/prepare/cells.h"
#include "render/prepare/packed_scene.h"
#include "render/prepare/pipeline_features.h"

namespace geodesic {
namespace {

Vec3 corner(const PackedScene& packed, uint32_t t, int i) {
  const Float4& x = packed.positions[3 * size_t(t) + i];
  return {x[0], x[1], x[2]};
}

bool same(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// Whether triangles t = (a, b, c) and s = (a, c, d) make a parallelogram, in that order: the
// shared diagonal's corners equal in float, d = a + c - b to float round-off, some area.
bool pair_of(const PackedScene& packed, uint32_t t, uint32_t s) {
  const Vec3 a = corner(packed, t, 0), b = corner(packed, t, 1), c = corner(packed, t, 2);
  if (!same(corner(packed, s, 0), a) || !same(corner(packed, s, 1), c)) return false;
  const double size = std::max(max_abs(b - a), max_abs(c - b));
  return size > 0 && max_abs(corner(packed, s, 2) - (a + c - b)) <= 1e-6 * size &&
         max_abs(cross(b - a, c - b)) > 1e-6 * size * size;
}

Vec3 chart_point(const Cell& chart, const Float4& model_point) {
  const Vec4 q =
      chart.chart_isometry * Vec4{model_point[0], model_point[1], model_point[2], model_point[3]};
  return q.xyz() / q.w;
}

// Everything the scene holds, as the points and balls (centre, radius) whose convex hull holds
// it, in the cell's chart.
struct SceneExtent {
  std::vector<Vec3> points;
  std::vector<std::pair<Vec3, double>> balls;
  double size = 1;  // the largest coordinate, for the tolerance

  bool on_one_side(const Vec3& n, double offset) const {
    const double tolerance = 1e-6 * size;
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec3& x : points)
      lo = std::min(lo, dot(n, x) - offset), hi = std::max(hi, dot(n, x) - offset);
    for (const auto& [c, r] : balls)
      lo = std::min(lo, dot(n, c) - offset - r), hi = std::max(hi, dot(n, c) - offset + r);
    return lo >= -tolerance || hi <= tolerance;
  }
};

SceneExtent scene_extent(const Cell& chart, uint32_t first, uint32_t count,
                         const PackedScene& packed) {
  SceneExtent extent;
  for (uint32_t t = first; t < first + count; ++t)
    for (int i = 0; i < 3; ++i) extent.points.push_back(corner(packed, t, i));
  for (const GpuPointLight& l : packed.lights)
    extent.points.push_back(chart_point(chart, l.position));
  for (const GpuSphere& s : packed.spheres)
    extent.balls.emplace_back(chart_point(chart, s.center), s.radius);
  for (const Vec3& x : extent.points) extent.size = std::max(extent.size, max_abs(x));
  for (const auto& [c, r] : extent.balls) extent.size = std::max(extent.size, max_abs(c) + r);
  return extent;
}

bool on_hull(const SceneExtent& extent, const PackedScene& packed, uint32_t t) {
  const Vec3 a = corner(packed, t, 0);
  const Vec3 n = cross(corner(packed, t, 1) - a, corner(packed, t, 2) - a);
  if (max_abs(n) == 0) return false;
  const Vec3 unit = n / length(n);
  return extent.on_one_side(unit, dot(unit, a));
}

}  // namespace

uint32_t list_cell_triangles(uint32_t first, uint32_t count, PackedScene& packed) {
  if (count > kTriangleListLength) return 0;
  const size_t begin = packed.listed.size();
  std::vector<bool> paired(count, false);
  for (uint32_t i = 0; i < count; ++i) {
    if (paired[i]) continue;
    GpuListedPrimitive listed{first + i, kUnpaired};
    for (uint32_t j = 0; j < count && listed.second == kUnpaired; ++j) {
      if (j == i || paired[j]) continue;
      if (pair_of(packed, first + i, first + j)) listed = {first + i, first + j};
      else if (pair_of(packed, first + j, first + i)) listed = {first + j, first + i};
      else continue;
      paired[j] = true;
    }
    paired[i] = true;
    packed.listed.push_back(listed);
  }
  // The pairs first: the shader tests them in one loop and the lone triangles in another.
  const auto lone = std::stable_partition(
      packed.listed.begin() + begin, packed.listed.end(),
      [](const GpuListedPrimitive& p) { return p.second != kUnpaired; });
  return uint32_t(lone - (packed.listed.begin() + begin));
}

void list_hull_first(bool euclidean, const Cell& chart, uint32_t first_triangle,
                     uint32_t triangle_count, bool holds_shapes, PackedScene& packed,
                     GpuCell& cell) {
  cell.listed_hull_pairs = cell.listed_hull_lone = 0;
  if (!euclidean || !chart.faces.empty() || holds_shapes || cell.listed_count == 0) return;
  const SceneExtent extent = scene_extent(chart, first_triangle, triangle_count, packed);
  const auto hull_first = [&](uint32_t begin, uint32_t end) {
    const auto first = packed.listed.begin() + begin;
    const auto rest = std::stable_partition(
        first, packed.listed.begin() + end,
        [&](const GpuListedPrimitive& p) { return on_hull(extent, packed, p.triangle); });
    return uint32_t(rest - first);
  };
  const uint32_t pairs_end = cell.listed_begin + cell.listed_pairs;
  cell.listed_hull_pairs = hull_first(cell.listed_begin, pairs_end);
  cell.listed_hull_lone = hull_first(pairs_end, cell.listed_begin + cell.listed_count);
}

}  // namespace geodesic
