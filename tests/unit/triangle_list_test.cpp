// The primitives a cell lists for TRIANGLE_LIST (render/prepare/triangle_list.h): two triangles
// that make a parallelogram are one primitive, every other triangle is its own, each triangle
// is listed exactly once, pairs come before lone triangles, and a cell of more triangles than
// the list's limit lists none. Those on the scene's hull, which shadow segments skip, come
// first: in the Cornell box its floor and three walls and not its ceiling (the light above it);
// none where something crosses their plane, nor in a quotient.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "render/prepare/packed_scene.h"
#include "render/prepare/pipeline_features.h"
#include "render/prepare/triangle_list.h"
#include "scene/scene_loader.h"

namespace geodesic {
namespace {

namespace fs = std::filesystem;

Vec3 corner(const PackedScene& p, uint32_t t, int i) {
  const auto& x = p.positions[3 * size_t(t) + i];
  return {x[0], x[1], x[2]};
}

// Every triangle of cell c listed once; pairs first, each a parallelogram (a, b, c), (a, c, d)
// with d = a + c - b. Returns the number of pairs.
uint32_t check_listing(const PackedScene& p, uint32_t c) {
  const gpu::Cell& cell = p.cells[c];
  const CellGeometry& g = p.cell_geometry[c];
  std::vector<int> seen(g.triangle_count, 0);
  uint32_t pairs = 0;
  for (uint32_t i = cell.listed_begin; i < cell.listed_begin + cell.listed_count; ++i) {
    const GpuListedPrimitive& l = p.listed[i];
    const bool pair = l.second != kUnpaired;
    EXPECT_EQ(pair, i < cell.listed_begin + cell.listed_pairs) << "listed " << i;
    for (const uint32_t t : {l.triangle, l.second}) {
      if (t == kUnpaired) continue;
      EXPECT_GE(t, g.first_triangle);
      EXPECT_LT(t, g.first_triangle + g.triangle_count);
      if (t >= g.first_triangle && t < g.first_triangle + g.triangle_count)
        ++seen[t - g.first_triangle];
    }
    if (!pair) continue;
    ++pairs;
    const Vec3 a = corner(p, l.triangle, 0), b = corner(p, l.triangle, 1),
               cc = corner(p, l.triangle, 2), d = corner(p, l.second, 2);
    EXPECT_EQ(length(corner(p, l.second, 0) - a), 0.0);
    EXPECT_EQ(length(corner(p, l.second, 1) - cc), 0.0);
    EXPECT_LE(length(d - (a + cc - b)), 1e-6 * length(cc - a));
  }
  for (uint32_t t = 0; t < g.triangle_count; ++t) EXPECT_EQ(seen[t], 1) << "triangle " << t;
  EXPECT_EQ(pairs, cell.listed_pairs);
  return pairs;
}

TEST(TriangleList, TheCornellBoxsSixteenTrianglesAreEightParallelograms) {
  const Scene scene = load_scene_file(fs::path(GEODESIC_SOURCE_DIR) / "scenes/cornell-box.json");
  const PackedScene packed = pack_scene(scene);
  ASSERT_EQ(packed.cells.size(), 1u);
  EXPECT_EQ(packed.cell_geometry[0].triangle_count, 16u);
  EXPECT_EQ(packed.cells[0].listed_count, 8u);
  EXPECT_EQ(check_listing(packed, 0), 8u);
  // The floor, back wall and two side walls on the hull, first; the four pieces of the ceiling
  // round its window (y = 1), with the light at y = 1.3 beyond their plane, after them.
  const gpu::Cell& cell = packed.cells[0];
  EXPECT_EQ(cell.listed_hull_pairs, 4u);
  EXPECT_EQ(cell.listed_hull_lone, 0u);
  for (uint32_t i = 0; i < cell.listed_pairs; ++i) {
    const GpuListedPrimitive& l = packed.listed[cell.listed_begin + i];
    bool ceiling = true;
    for (int k = 0; k < 3; ++k) ceiling = ceiling && corner(packed, l.triangle, k).y == 1.0;
    EXPECT_EQ(ceiling, i >= cell.listed_hull_pairs) << "listed " << i;
  }
}

// A quad floor under a sphere and a light: on the hull, unless a sphere reaches below it or
// the space is a quotient.
TEST(TriangleList, APlaneIsOnTheHullOnlyWithEverythingOnOneSide) {
  const auto floor_under = [](double sphere_y, const std::string& more = "", double lift = 0) {
    const auto doc = nlohmann::ordered_json::parse(R"({
      "geometry": "euclidean", "camera": {"position": [0, 0, 9]}, "materials": {"m": {}},
      "objects": [
        {"type": "quad", "material": "m", "corner": [-1, )" + std::to_string(lift) +
        R"(, -1], "edge_u": [0, 0, 2], "edge_v": [2, 0, 0]},
        {"type": "sphere", "material": "m", "center": [0, )" + std::to_string(lift + sphere_y) +
        R"(, 0], "radius": 0.5})" + more + R"(],
      "lights": [{"type": "point", "position": [0, )" + std::to_string(lift + 3) +
        R"(, 0], "intensity": 1}]})");
    const PackedScene packed = pack_scene(parse_scene(doc, {}));
    EXPECT_EQ(packed.cells[0].listed_pairs, 1u);
    return packed.cells[0].listed_hull_pairs;
  };
  EXPECT_EQ(floor_under(0.5), 1u);  // resting on it
  EXPECT_EQ(floor_under(0.4), 0u);  // sunk 0.1 below it
  // The same a thousand units up, where the tolerance grows with the coordinates.
  EXPECT_EQ(floor_under(0.5, "", 1000), 1u);
  EXPECT_EQ(floor_under(0.49, "", 1000), 0u);
  // A small sphere beside it, across its plane.
  EXPECT_EQ(floor_under(0.5, R"(, {"type": "sphere", "material": "m", "center": [3, 0, 0],
                                    "radius": 0.01})"),
            0u);
  const PackedScene torus =
      pack_scene(load_scene_file(fs::path(GEODESIC_SOURCE_DIR) / "scenes/torus-cornell.json"));
  for (const gpu::Cell& cell : torus.cells)
    EXPECT_EQ(cell.listed_hull_pairs + cell.listed_hull_lone, 0u);
}

TEST(TriangleList, QuadsAndARotatedBoxPairUpAndAPolygonsFanStaysLone) {
  const auto doc = nlohmann::ordered_json::parse(R"({
    "geometry": "euclidean", "camera": {"position": [0, 0, 9]}, "materials": {"m": {}},
    "objects": [
      {"type": "polygon", "material": "m",
       "vertices": [[0, 0, -2], [1, 0, -2], [1.3, 0.8, -2], [0.5, 1.4, -2], [-0.3, 0.8, -2]]},
      {"type": "quad", "material": "m", "corner": [-1, -1, -1], "edge_u": [2, 0, 0],
       "edge_v": [0.3, 0, 2]},
      {"type": "box", "material": "m", "min": [0.1, -0.6, 0.3], "max": [0.6, -0.5, 0.4],
       "rotation": {"yaw": 30, "pitch": 10}}]})");
  const PackedScene packed = pack_scene(parse_scene(doc, {}));
  ASSERT_EQ(packed.cells.size(), 1u);
  const uint32_t triangles = packed.cell_geometry[0].triangle_count;
  EXPECT_EQ(check_listing(packed, 0), 7u);  // the quad and the box's six faces
  EXPECT_EQ(packed.cells[0].listed_count, triangles - 7);
  EXPECT_GT(packed.cells[0].listed_count, packed.cells[0].listed_pairs);  // the fan
}

TEST(TriangleList, TorusCornellsCellsAreListedAndAMeshPastTheLimitIsNot) {
  const Scene torus_scene =
      load_scene_file(fs::path(GEODESIC_SOURCE_DIR) / "scenes/torus-cornell.json");
  const PackedScene torus = pack_scene(torus_scene);
  for (uint32_t c = 0; c < torus.cells.size(); ++c) EXPECT_GT(check_listing(torus, c), 0u);
  EXPECT_TRUE(scene_features(torus_scene, torus).triangle_list);
  // Seventeen quads: 34 triangles, past kTriangleListLength.
  std::string objects;
  for (int i = 0; i < 17; ++i)
    objects += std::string(i ? "," : "") + R"({"type": "quad", "material": "m", "corner": [)" +
               std::to_string(0.1 * i) + R"(, 0, -1], "edge_u": [0.05, 0, 0], "edge_v": [0, 1, 0]})";
  const auto doc = nlohmann::ordered_json::parse(
      R"({"geometry": "euclidean", "camera": {"position": [0, 0, 9]}, "materials": {"m": {}},
          "objects": [)" + objects + "]}");
  const PackedScene packed = pack_scene(parse_scene(doc, {}));
  ASSERT_GT(packed.cell_geometry[0].triangle_count, kTriangleListLength);
  EXPECT_EQ(packed.cells[0].listed_count, 0u);
  EXPECT_EQ(packed.cells[0].listed_pairs, 0u);
}

}  // namespace
}  // namespace geodesic
