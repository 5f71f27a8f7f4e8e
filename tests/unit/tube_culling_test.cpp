// Edge-tube culling (render/tube_culling.h): in every bundled quotient scene with edge tubes,
// each tube finds the two faces that hold its axis, and no chart segment that meets a tube
// has it culled. Segments run face to face through the domain, most of them starting beside
// an edge, where the tubes are.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "geometry/capsule.h"
#include "render/cells.h"
#include "render/packed_scene.h"
#include "render/tube_culling.h"
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
  // Each face's range holds exactly the tubes it is the first face of.
  for (uint32_t f = 0; f < cell.faces.size(); ++f) {
    const uint32_t range = packed.faces[f].tubes;
    for (uint32_t i = range & 0xFFFF; i < (range & 0xFFFF) + (range >> 16); ++i)
      EXPECT_EQ(packed.tubes[i].face_a, f);
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
    for (const GpuTube& t : packed.tubes) {
      const Capsule c{{t.a[0], t.a[1], t.a[2]}, {t.b[0], t.b[1], t.b[2]}, t.a[3]};
      const bool may = tube_may_meet(near, t.face_a, t.face_b);
      tested += may;
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
