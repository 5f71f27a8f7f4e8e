// The order primitives are packed in (render/spatial_order.h): a permutation whose halving at
// every (first + last) / 2, as Mesa lavapipe's acceleration-structure build halves it, is a
// split in space; and the packed scene keeps every triangle and sphere with its own data.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <random>
#include <set>

#include "render/packed_scene.h"
#include "render/spatial_order.h"
#include "scene/scene_loader.h"

namespace geodesic {
namespace {

std::vector<Vec3> random_points(int count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) points.push_back({u(rng), u(rng), 10 * u(rng)});
  return points;
}

// Every range [first, last] halves into two parts that a plane normal to an axis separates.
void expect_spatial_splits(const std::vector<Vec3>& c, const std::vector<uint32_t>& order,
                           size_t first, size_t last) {
  if (last <= first) return;
  const size_t middle = (first + last) / 2;
  bool separated = false;
  for (int axis = 0; axis < 3; ++axis) {
    double left = -INFINITY, right = INFINITY;
    for (size_t i = first; i <= middle; ++i) left = std::max(left, c[order[i]][axis]);
    for (size_t i = middle + 1; i <= last; ++i) right = std::min(right, c[order[i]][axis]);
    separated = separated || left <= right;
  }
  ASSERT_TRUE(separated) << "range " << first << ".." << last;
  expect_spatial_splits(c, order, first, middle);
  expect_spatial_splits(c, order, middle + 1, last);
}

// The summed volume of the boxes of a tree built by halving index ranges (lavapipe's build):
// what a ray pays for, up to the distribution of rays.
double tree_box_volume(const std::vector<Vec3>& c, const std::vector<uint32_t>& order,
                       size_t first, size_t last) {
  Vec3 lo = c[order[first]], hi = lo;
  for (size_t i = first; i <= last; ++i) {
    const Vec3& p = c[order[i]];
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double volume = (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z);
  if (last <= first) return volume;
  const size_t middle = (first + last) / 2;
  return volume + tree_box_volume(c, order, first, middle) +
         tree_box_volume(c, order, middle + 1, last);
}

TEST(SpatialOrder, IsAPermutationWhoseIndexHalvingsSplitSpace) {
  for (const int count : {0, 1, 2, 3, 7, 64, 1000, 1027}) {
    const std::vector<Vec3> points = random_points(count, uint32_t(count));
    const std::vector<uint32_t> order = median_split_order(points);
    ASSERT_EQ(order.size(), size_t(count));
    EXPECT_EQ(std::set<uint32_t>(order.begin(), order.end()).size(), size_t(count));
    if (count > 0) expect_spatial_splits(points, order, 0, order.size() - 1);
  }
}

TEST(SpatialOrder, ShrinksTheBoxesOfAnIndexHalvingTree) {
  const std::vector<Vec3> points = random_points(3000, 7);
  std::vector<uint32_t> as_given(points.size());
  for (uint32_t i = 0; i < as_given.size(); ++i) as_given[i] = i;
  const double given = tree_box_volume(points, as_given, 0, points.size() - 1);
  const double ordered = tree_box_volume(points, median_split_order(points), 0, points.size() - 1);
  // As given (random), the boxes of the upper thousand nodes or so are each about the whole
  // scene's 40 units^3; in order they shrink level by level (measured: 55660 against 708).
  EXPECT_GT(given, 40.0 * 1000);
  EXPECT_LT(ordered, given / 50);
}

// The mirrored dodecahedron's spheres and edge tubes: packing reorders them, and keeps each
// triangle's three chart vertices with its material and each sphere ref with its own box.
TEST(SpatialOrder, PackingKeepsEveryTriangleAndSphereWithItsData) {
  const Scene scene = load_scene_file(GEODESIC_SOURCE_DIR "/scenes/mirrored-dodecahedron.json");
  const PackedScene packed = pack_scene(scene);
  size_t mesh_triangles = 0;
  for (const TriangleMesh& mesh : scene.meshes) mesh_triangles += mesh.indices.size() / 3;
  ASSERT_EQ(packed.cell_geometry.size(), 1u);
  EXPECT_EQ(packed.triangles.size(), mesh_triangles);
  std::printf("mirrored dodecahedron: %zu tube triangles packed\n", mesh_triangles);
  // Each packed triangle is one of the tubes' triangles, every one exactly once.
  using Key = std::array<float, 9>;
  std::multiset<Key> expected, got;
  for (const TriangleMesh& mesh : scene.meshes)
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
      Key key;
      for (int i = 0; i < 3; ++i) {
        const Vec4 q = model::exp_origin(scene.geometry, mesh.positions[mesh.indices[t + i]]);
        for (int j = 0; j < 3; ++j) key[3 * i + j] = float(q.xyz()[j] / q.w);
      }
      expected.insert(key);
    }
  for (size_t t = 0; t < packed.triangles.size(); ++t) {
    Key key;
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(packed.indices[3 * t + i], 3 * t + i);
      for (int j = 0; j < 3; ++j) key[3 * i + j] = packed.positions[3 * t + i][j];
    }
    got.insert(key);
    EXPECT_EQ(packed.triangles[t].material, scene.meshes[0].material);
  }
  EXPECT_TRUE(got == expected);
  // Sphere refs: every sphere once, inside its own box.
  ASSERT_EQ(packed.sphere_refs.size(), scene.spheres.size());
  std::set<uint32_t> spheres;
  for (size_t r = 0; r < packed.sphere_refs.size(); ++r) {
    const uint32_t s = packed.sphere_refs[r].sphere;
    spheres.insert(s);
    const Vec4 centre = model::exp_origin(scene.geometry, scene.spheres[s].center);
    for (int j = 0; j < 3; ++j) {
      EXPECT_LT(packed.sphere_bounds[r].min[j], centre.xyz()[j] / centre.w);
      EXPECT_GT(packed.sphere_bounds[r].max[j], centre.xyz()[j] / centre.w);
    }
  }
  EXPECT_EQ(spheres.size(), scene.spheres.size());
}

}  // namespace
}  // namespace geodesic
