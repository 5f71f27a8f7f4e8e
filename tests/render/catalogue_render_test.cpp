// The catalogue's bundled scenes (scenes/catalogue/<name>.json, spaces known only by their
// generators): each renders without a non-finite sample, at its own depth and at depth 64, and
// shows its spheres (a closed E3 or H3 space at the largest crossing cap, few of its geodesics
// cut off there), and camera rays traced in double precision across the faces always land back
// inside the Dirichlet domain (inside the cell they continue in, for domains cut into pieces
// charted apart).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "twins/cell_tracer.h"
#include "render_fixture.h"
#include "scene/catalogue.h"

namespace geodesic::test {
namespace {

// How far model point p lies outside cell c (<= 0: inside), relative to the face offsets.
double outside(GeometryKind k, const std::vector<Cell>& cells, int c, const Vec4& p) {
  const Vec3 x = model::chart(k, cells[c].chart_isometry * p);
  double worst = -INFINITY;
  for (const CellFace& f : cells[c].faces)
    worst = std::max(worst, (dot(f.normal, x) - f.delta) / std::max(1.0, std::abs(f.delta)));
  return worst;
}

// Whether the H3 geodesic (p, v) runs into an ideal vertex of the (one-cell) domain: its end
// at infinity, the null vector p + v, is the vertex. Such a geodesic stays in the cusp's
// chimney, between faces that meet it only at infinity: it leaves the cell, if at all, at
// infinite distance (the renderer ends it on the cusp's horosphere).
bool runs_into_cusp(const Scene& scene, const Cell& cell, const CellRay& ray) {
  if (scene.geometry != GeometryKind::Hyperbolic) return false;
  const Vec4 end = cell.chart_isometry * (ray.p + ray.v);
  for (const Vec3& v : scene.manifold.domain.vertices)
    if (ideal_vertex(scene.geometry, v) && length(end.xyz() / end.w - v) < 1e-6) return true;
  return false;
}

TEST(CatalogueScenes, RenderFiniteAndEveryRayEndsInTheCell) {
  for (const CatalogueEntry& entry : catalogue()) {
    SCOPED_TRACE(entry.name);
    Scene scene = load_scene_file(source_path("scenes/catalogue/" + entry.name + ".json"));
    ASSERT_EQ(scene.geometry, entry.kind);
    ASSERT_FALSE(scene.manifold.faces.empty() && scene.manifold.pieces.empty());

    // Double twin: a 9 x 9 fan of camera rays through max_crossings faces each.
    const auto cells = build_cells(scene);
    const double tan_half = std::tan(scene.camera.fov_y_degrees * M_PI / 360);
    int crossings = 0, into_cusps = 0;
    for (int i = 0; i < 81; ++i) {
      const Vec3 d = normalize({(i % 9 - 4) / 4.0 * tan_half, (i / 9 - 4) / 4.0 * tan_half, -1});
      const CameraPlacement camera = place_camera(entry.kind, cells, scene.camera.pose);
      CellRay ray{camera.pose * model::origin(), camera.pose * Vec4(d, 0), int(camera.cell), -1};
      ASSERT_LT(outside(entry.kind, cells, ray.cell, ray.p), 1e-9) << "the camera";
      for (int c = 0; c < scene.manifold.max_crossings; ++c) {
        const CellExit exit = exit_cell(entry.kind, cells, ray);
        if ((exit.face < 0 || !std::isfinite(exit.t)) && runs_into_cusp(scene, cells[ray.cell], ray)) {
          ++into_cusps;
          break;
        }
        ASSERT_GE(exit.face, 0) << "ray " << i << " after crossing " << c;
        ASSERT_TRUE(std::isfinite(exit.t)) << "ray " << i << " after crossing " << c << ": face " << exit.face << " t " << exit.t;
        ray = cross_face(entry.kind, cells, ray, exit.face, exit.t);
        ASSERT_LT(outside(entry.kind, cells, ray.cell, ray.p), 1e-9)
            << "ray " << i << " after crossing " << c;
        ++crossings;
      }
    }
    if (into_cusps == 0) EXPECT_EQ(crossings, 81 * scene.manifold.max_crossings);
    EXPECT_LE(into_cusps, 1) << "only the central ray aims at a cusp";

    // In a closed E3 or H3 space every geodesic meets something in the end: one cut off at
    // the crossing cap is black where the scene is not, so their scenes take the largest cap
    // (at 24 the tori were 12 % too dark). Then at most 2 % of the paths hold a cut-off
    // geodesic (0.2-0.9 % at 64x64; 2-21 % at 24), except in the spaces whose thin domains need
    // more crossings than the largest cap (docs/numerics.md).
    // (A cusped space, H3 too, has the largest cap as well.)
    const bool not_spherical = entry.kind != GeometryKind::Spherical;
    if (not_spherical) EXPECT_EQ(scene.manifold.max_crossings, kMaxCrossings);
    const bool thin = entry.name.starts_with("coxeter-") || entry.name.ends_with("-amphicosm");
    const int size = 24, spp = 4;
    scene.render.width = scene.render.height = size;
    scene.render.russian_roulette = false;  // the depth-64 paths below run their full length
    try {
      Renderer renderer(device(), scene);
      renderer.add_samples(spp);
      EXPECT_EQ(renderer.non_finite_samples(), 0u);
      if (not_spherical && !thin)
        EXPECT_LE(renderer.trace_counters().truncated_rays, 0.02 * spp * size * size);
      const Image image = renderer.image();
      int lit = 0;
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
          lit += image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2) > 0.05;
      EXPECT_GT(lit, size * size / 12) << "the spheres and their copies should fill part of the view";
      // Paths of 64 bounces, each bounce's geodesics up to the crossing cap: no sample may
      // come out NaN or infinite, however long the walk.
      renderer.set_sampling(64, scene.render.light_samples);
      renderer.reset();
      renderer.add_samples(2);
      EXPECT_EQ(renderer.non_finite_samples(), 0u) << "at depth 64";
      const Image deep = renderer.image();
      EXPECT_EQ(std::count_if(deep.rgb.begin(), deep.rgb.end(),
                              [](float v) { return !std::isfinite(v); }),
                0)
          << "non-finite pixel values at depth 64";
    } catch (const std::exception& e) {
      ADD_FAILURE() << "render failed: " << e.what();  // and go on with the next entry
    }
  }
}

// The default scenes of the spherical spaces (scene/spherical_view.h), at 32 x 32. A light all
// of whose images together bring its spheres a set irradiance leaves them their colour: at
// the lone light's intensity the binary icosahedral, octahedral and L(11,3) scenes were washed
// out, their lit pixels, clipped to 1, greyer (smallest channel over largest 0.57-0.69 on
// average) than any now (0.22-0.39; 0.27-0.52 before in the others). And no edge tube lies at
// the camera's antipode, where it would fill the whole background: in L(5,2) one did, every
// pixel lit and 55 % of them the tubes' yellow (now at most 23 % in any of these scenes).
TEST(CatalogueScenes, SphericalDefaultsKeepTheirColourAndAClearBackground) {
  for (const CatalogueEntry& entry : catalogue()) {
    if (entry.kind != GeometryKind::Spherical) continue;
    SCOPED_TRACE(entry.name);
    Scene scene = load_scene_file(source_path("scenes/catalogue/" + entry.name + ".json"));
    const int size = 32;
    scene.render.width = scene.render.height = size;
    Renderer renderer(device(), scene);
    renderer.add_samples(16);
    const Image image = renderer.image();
    int lit = 0, edge = 0;
    double grey = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const float r = image.at(x, y, 0), g = image.at(x, y, 1), b = image.at(x, y, 2);
        if (r + g + b <= 0.05f) continue;
        ++lit;
        grey += std::min({r, g, b, 1.0f}) / std::min(std::max({r, g, b}), 1.0f);
        edge += g > 0.6f * r && b < 0.6f * r && b < 0.6f * g;  // the tubes' (0.85, 0.7, 0.35)
      }
    ASSERT_GT(lit, 0);
    EXPECT_LT(grey / lit, 0.55) << "washed out";
    EXPECT_LT(edge, lit / 3) << "an edge at the camera's antipode";
  }
}

}  // namespace
}  // namespace geodesic::test
