#include "render/prepare/triangle_list.h"

#include <algorithm>
#include <cmath>

#include "geometry/vec.h"
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

}  // namespace geodesic
