// Scenes whose answer is known in closed form.
#include <cmath>

#include "render_fixture.h"

namespace geodesic::test {
namespace {

// A closed cube room, every wall emitting Le and reflecting diffusely with albedo rho; the
// camera inside sees radiance Le * (1 - rho^(d+1)) / (1 - rho) after d bounces. Under the
// paper's model every path brings exactly that (no light sampling): zero variance.
std::string furnace(double rho, double le, int depth) {
  return R"({
    "geometry": "euclidean",
    "camera": {"position": [0.1, 0.2, 0.3], "look_at": [1, -0.5, -1], "fov_y": 90},
    "materials": {"wall": {"diffuse": )" + std::to_string(rho) + R"(, "emission": )" +
         std::to_string(le) + R"(}},
    "objects": [{"type": "box", "min": [-2, -2, -2], "max": [2, 2, 2], "material": "wall"},
                {"type": "sphere", "center": [0.5, -1, -1], "radius": 0.5, "material": "wall"}],
    "render": {"width": 32, "height": 32, "lighting": "paper", "max_depth": )" +
         std::to_string(depth) + R"(}
  })";
}

class BothBackends : public ::testing::TestWithParam<BackendKind> {};

TEST_P(BothBackends, WhiteFurnaceConvergesToEmissionOverOneMinusAlbedo) {
  const double rho = 0.5, le = 1.0;
  const int depth = 40;
  const Image image = render(scene_from_json(furnace(rho, le, depth)), 4, GetParam());
  const double expected = le * (1 - std::pow(rho, depth + 1)) / (1 - rho);
  ASSERT_NEAR(expected, le / (1 - rho), 1e-9);  // depth 40 is converged
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(image.at(x, y, c), expected, 0.01 * expected) << "pixel " << x << "," << y;
}

TEST_P(BothBackends, EmissiveOnlySceneShowsItsEmission) {
  const Image image = render(scene_from_json(R"({
    "geometry": "euclidean",
    "camera": {"position": [0, 0, 3], "look_at": [0, 0, 0], "fov_y": 40},
    "materials": {"glow": {"emission": [0.2, 0.5, 0.8]}},
    "objects": [{"type": "quad", "corner": [-5, -5, 0], "edge_u": [10, 0, 0], "edge_v": [0, 10, 0],
                 "material": "glow"}],
    "render": {"width": 16, "height": 16}
  })"), 2, GetParam());
  const Rgb m = mean(image);
  EXPECT_NEAR(m.r, 0.2, 1e-5);
  EXPECT_NEAR(m.g, 0.5, 1e-5);
  EXPECT_NEAR(m.b, 0.8, 1e-5);
}

INSTANTIATE_TEST_SUITE_P(Render, BothBackends,
                         ::testing::Values(BackendKind::RayQuery, BackendKind::RayTracingPipeline),
                         [](const auto& info) {
                           return info.param == BackendKind::RayQuery ? "RayQuery" : "Pipeline";
                         });

}  // namespace
}  // namespace geodesic::test

namespace geodesic::test {
namespace {

// Russian roulette changes which paths get traced, not the expected image: the furnace still
// converges to Le / (1 - rho) over the image.
TEST(RussianRoulette, KeepsTheFurnaceUnbiased) {
  Scene scene = scene_from_json(furnace(0.5, 1.0, 40));
  scene.render.russian_roulette = true;
  const Image image = render(scene, 64);
  const Rgb m = mean(image);
  EXPECT_NEAR(m.r, 2.0, 0.01 * 2.0);
  EXPECT_NEAR(m.g, 2.0, 0.01 * 2.0);
  // ... and it is a real Monte Carlo estimate now: pixels differ.
  EXPECT_GT(rms_difference(image, render(scene_from_json(furnace(0.5, 1.0, 40)), 1)), 1e-3);
}

}  // namespace
}  // namespace geodesic::test
