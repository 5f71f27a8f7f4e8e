// A cell's content box (gpu::Cell content_lo / content_hi, render/prepare/packed_scene.cpp):
// the shader skips the traversal of a segment that misses it, so it must hold every triangle
// vertex, sphere box and shape box of its cell with room to spare for a float slab test, stay
// close to them (or skipping gains nothing), and be empty (lo > hi) in a cell that traces
// nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "render/prepare/packed_scene.h"
#include "scene/scene_loader.h"

namespace geodesic {
namespace {

struct Box {
  double lo[3] = {INFINITY, INFINITY, INFINITY};
  double hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  void add(const float* lo_in, const float* hi_in) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], double(lo_in[i]));
      hi[i] = std::max(hi[i], double(hi_in[i]));
    }
  }
  bool empty() const { return lo[0] > hi[0]; }
};

// What the cell's primitives span, found from the packed ranges themselves.
Box primitives_of(const PackedScene& packed, uint32_t c) {
  Box box;
  const CellGeometry& g = packed.cell_geometry[c];
  for (uint32_t t = g.first_triangle; t < g.first_triangle + g.triangle_count; ++t)
    for (int v = 0; v < 3; ++v) box.add(packed.positions[3 * t + v].data(), packed.positions[3 * t + v].data());
  for (uint32_t r = g.first_sphere_ref; r < g.first_sphere_ref + g.sphere_ref_count; ++r)
    box.add(packed.sphere_bounds[r].min, packed.sphere_bounds[r].max);
  for (uint32_t r = g.first_shape_ref; r < g.first_shape_ref + g.shape_ref_count; ++r)
    box.add(packed.shape_bounds[r].min, packed.shape_bounds[r].max);
  return box;
}

TEST(ContentBox, HoldsEveryPrimitiveOfItsCellWithRoomForFloatAndNoMore) {
  int cells = 0, empty_cells = 0;
  for (const char* name : {"mirrored-dodecahedron", "quarter-turn-space", "seifert-weber",
                           "torus-cornell", "torus-lamps", "poincare-sphere", "figure-eight-knot",
                           "spherical-spheres", "cornell-box", "mesh-demo"}) {
    SCOPED_TRACE(name);
    const Scene scene =
        load_scene_file(std::string(GEODESIC_SOURCE_DIR "/scenes/") + name + ".json");
    const PackedScene packed = pack_scene(scene);
    ASSERT_EQ(packed.cells.size(), packed.cell_geometry.size());
    for (uint32_t c = 0; c < packed.cells.size(); ++c) {
      SCOPED_TRACE("cell " + std::to_string(c));
      const gpu::Cell& cell = packed.cells[c];
      const Box spans = primitives_of(packed, c);
      ++cells;
      if (spans.empty()) {
        ++empty_cells;
        for (int i = 0; i < 3; ++i) EXPECT_GT(cell.content_lo[i], cell.content_hi[i]);
        continue;
      }
      for (int i = 0; i < 3; ++i) {
        // Room: past the primitives' own boxes by at least 1e-5 of the coordinate, far more
        // than a float slab test's rounding (~1e-7 of it).
        const double room_lo = 1e-5 * (1 + std::abs(spans.lo[i]));
        const double room_hi = 1e-5 * (1 + std::abs(spans.hi[i]));
        EXPECT_LE(cell.content_lo[i], spans.lo[i] - room_lo);
        EXPECT_GE(cell.content_hi[i], spans.hi[i] + room_hi);
        // No more than the padding past them.
        EXPECT_GE(cell.content_lo[i], spans.lo[i] - 3e-4 * (1 + std::abs(spans.lo[i])));
        EXPECT_LE(cell.content_hi[i], spans.hi[i] + 3e-4 * (1 + std::abs(spans.hi[i])));
      }
    }
  }
  std::printf("%d cells, %d of them tracing nothing\n", cells, empty_cells);
  EXPECT_GT(empty_cells, 0) << "no cell without content: the empty case went untested";
}

}  // namespace
}  // namespace geodesic
