// Edge-tube culling (render/prepare/tube_culling.h): in every bundled quotient scene with edge tubes,
// each tube finds the two faces that hold its axis, the shader's lookup by pairs of near faces
// (tubes_to_test) finds exactly the tubes on such pairs, and no chart segment that meets a tube
// has it culled. Segments run face to face through the domain, most of them starting beside
// an edge, where the tubes are.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "geometry/capsule.h"
#include "render/prepare/cells.h"
#include "render/prepare/packed_scene.h"
#include "render/prepare/tube_culling.h"
#include "scene/scene_loader.h"

namespace geodesic {
namespace {

Vec3 unit3(std::mt19937_64& gen) {
  std::normal_distribution<double> normal;
  return normalize(Vec3{normal(gen), normal(gen), normal(gen)});
}

// Where the chart line o + s d leaves the cell (s > 0), or back to where it entered (s < 0).
double face_parameter(const Cell& cell, const Vec3& o, const Vec3& d, bool forward) {
  double best = forward ? 1e30 : -1e30;
  for (const CellFace& f : cell.faces) {
    const double towards = dot(f.normal, d);
    if (forward ? towards <= 0 : towards >= 0) continue;
    const double s = (f.delta - dot(f.normal, o)) / towards;
    best = forward ? std::min(best, s) : std::max(best, s);
  }
  return best;
}

class TubeCulling : public ::testing::TestWithParam<std::string> {};

TEST_P(TubeCulling, EveryTubeHasItsTwoFacesAndNoMetTubeIsCulled) {
  const Scene scene = load_scene_file(std::filesystem::path(GEODESIC_SOURCE_DIR) / GetParam());
  const std::vector<Cell> cells = build_cells(scene);
  ASSERT_EQ(cells.size(), 1u);
  const Cell& cell = cells[0];
  const PackedScene packed = pack_scene(scene);
  ASSERT_EQ(packed.tubes.size(), scene.tubes.size());
  EXPECT_EQ(packed.cells[0].always_begin, packed.tubes.size());  // none tested always
  for (const GpuTube& t : packed.tubes) {
    ASSERT_LT(t.face_a, t.face_b);
    ASSERT_LT(t.face_b, cell.faces.size());
  }
  // Each face's tubes are those it is the first face of, one per second face, found where
  // its tube_partners bits say.
  for (uint32_t f = 0; f < cell.faces.size(); ++f) {
    const uint32_t partners = packed.faces[f].tube_partners;
    EXPECT_EQ(std::count_if(packed.tubes.begin(), packed.tubes.end(),
                            [&](const GpuTube& t) { return t.face_a == f; }),
              std::popcount(partners));
    for (uint32_t j = 0; j < 32; ++j)
      if ((partners >> j) & 1u) {
        const GpuTube& t =
            packed.tubes[packed.faces[f].tubes + std::popcount(partners & ((1u << j) - 1))];
        EXPECT_EQ(t.face_a, f);
        EXPECT_EQ(t.face_b, j);
      }
  }
  const Polyhedron& domain = scene.manifold.domain;
  Vec3 centroid;
  for (const Vec3& v : domain.vertices) centroid += v / double(domain.vertices.size());
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(0, 1);
  int met = 0;
  double tested = 0;
  constexpr int kSegments = 20000;
  for (int n = 0; n < kSegments; ++n) {
    const auto& edge = domain.edges[gen() % domain.edges.size()];
    const Vec3 a = domain.vertices[edge[0]], b = domain.vertices[edge[1]];
    // Beside an edge (three in four) or anywhere inside, then back to the face it came in by.
    const double inward = n % 4 == 0 ? u(gen) : 0.05 * u(gen);
    const Vec3 inside = a + u(gen) * (b - a) + inward * (centroid - (a + 0.5 * (b - a)));
    const Vec3 d = unit3(gen);
    const Vec3 o = inside + face_parameter(cell, inside, d, false) * d;
    const double s_max = face_parameter(cell, o, d, true);
    const uint32_t near = near_faces(cell, o, d, s_max, packed.cells[0].tube_reach);
    // The shader's lookup finds exactly the tubes on pairs of near faces, and no tube the
    // segment meets is left out.
    const std::vector<uint32_t> found = tubes_to_test(packed.cells[0], packed.faces, near);
    tested += double(found.size());
    for (uint32_t i = 0; i < packed.tubes.size(); ++i) {
      const GpuTube& t = packed.tubes[i];
      const bool may = tube_may_meet(near, t.face_a, t.face_b);
      ASSERT_EQ(std::count(found.begin(), found.end(), i), may ? 1 : 0) << "tube " << i;
      const Capsule c{{t.a[0], t.a[1], t.a[2]}, {t.b[0], t.b[1], t.b[2]}, t.a[3]};
      if (std::isinf(intersect_capsule(c, o, d, 0, s_max))) continue;
      ++met;
      ASSERT_TRUE(may) << "segment " << n << " meets a tube held by faces " << t.face_a << ", "
                       << t.face_b;
    }
  }
  std::printf("%s: %zu tubes, %.2f tested per segment, %d tube hits in %d segments\n",
              GetParam().c_str(), packed.tubes.size(), tested / kSegments, met, kSegments);
  EXPECT_GT(met, kSegments / 20);
  EXPECT_LT(tested / kSegments, 0.25 * double(packed.tubes.size()));
}

// A segment from the middle of one face to the middle of a face beside it passes their common
// edge far away: the first face is within reach only at its start, the second only at its end,
// so no face counts as near and no tube is tested. Started at the middle of the edge instead,
// both faces are within reach at its start, and the tube on their edge is tested.
TEST_P(TubeCulling, ASegmentFarFromTheEdgesTestsNoTube) {
  const Scene scene = load_scene_file(std::filesystem::path(GEODESIC_SOURCE_DIR) / GetParam());
  const std::vector<Cell> cells = build_cells(scene);
  const Cell& cell = cells.at(0);
  const PackedScene packed = pack_scene(scene);
  const double reach = packed.cells[0].tube_reach;
  const Polyhedron& domain = scene.manifold.domain;
  const auto middle = [&](uint32_t f) {  // the mean of face f's vertices
    Vec3 sum;
    int count = 0;
    for (const Vec3& v : domain.vertices)
      if (std::abs(dot(cell.faces[f].normal, v) - cell.faces[f].delta) < 1e-9) {
        sum += v;
        ++count;
      }
    EXPECT_GE(count, 3) << "face " << f;
    return sum / double(count);
  };
  for (const GpuTube& t : packed.tubes) {
    const Vec3 a = middle(t.face_a), b = middle(t.face_b);
    EXPECT_EQ(near_faces(cell, a, b - a, 1.0, reach), 0u) << t.face_a << ", " << t.face_b;
    const Vec3 edge = 0.5 * (Vec3{t.a[0], t.a[1], t.a[2]} + Vec3{t.b[0], t.b[1], t.b[2]});
    const uint32_t pair = (1u << t.face_a) | (1u << t.face_b);
    EXPECT_EQ(near_faces(cell, edge, b - edge, 1.0, reach) & pair, pair);
  }
}

// Three tubes on one edge (a document that asks for the domain's edges three times): the
// lookup finds one per pair of faces, so the others on each edge go to the tubes always
// tested, and every tube is still tested where it can be met.
TEST(TubeCulling, ExtraTubesOnOneEdgeAreAlwaysTested) {
  Scene scene = load_scene_file(std::filesystem::path(GEODESIC_SOURCE_DIR) /
                                "scenes/mirrored-dodecahedron.json");
  const std::vector<EdgeTube> edges = scene.tubes;
  for (int copy = 0; copy < 2; ++copy)
    scene.tubes.insert(scene.tubes.end(), edges.begin(), edges.end());
  const PackedScene packed = pack_scene(scene);
  ASSERT_EQ(packed.tubes.size(), 3 * edges.size());
  EXPECT_EQ(packed.cells[0].always_begin, edges.size());
  for (size_t i = edges.size(); i < packed.tubes.size(); ++i)
    EXPECT_EQ(packed.tubes[i].face_a, kAlwaysTest);
  const uint32_t every_face = (1u << packed.cells[0].face_count) - 1;
  std::vector<uint32_t> all = tubes_to_test(packed.cells[0], packed.faces, every_face);
  std::sort(all.begin(), all.end());
  EXPECT_EQ(std::adjacent_find(all.begin(), all.end()), all.end());  // each tube once
  EXPECT_EQ(all.size(), 3 * edges.size());
  EXPECT_EQ(tubes_to_test(packed.cells[0], packed.faces, 0).size(), 2 * edges.size());
}

INSTANTIATE_TEST_SUITE_P(
    BundledQuotients, TubeCulling,
    ::testing::Values("scenes/mirrored-dodecahedron.json", "scenes/seifert-weber.json",
                      "scenes/poincare-sphere.json", "scenes/quarter-turn-space.json",
                      "scenes/catalogue/coxeter-5-3-4.json", "scenes/catalogue/lens-7-3.json"),
    [](const auto& info) {
      std::string name = std::filesystem::path(info.param).stem().string();
      for (char& c : name)
        if (c == '-') c = '_';
      return name;
    });

}  // namespace
}  // namespace geodesic
