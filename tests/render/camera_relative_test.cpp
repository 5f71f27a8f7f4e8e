// Camera-relative numerics (render/device/renderer.h, docs/numerics.md): a scene moved far from the
// origin by an isometry renders the image it renders at the origin, within the seed-to-seed
// noise, with no non-finite sample: H3 up to 20 units out (the float-only renderer had
// fireflies from 4 and NaN at 8; composing the frame in double lost the scene from 12), E3 with
// its contact shadow 1e6 out.
#include <string>

#include "render/service/render_service.h"
#include "render_fixture.h"
#include "scene/scene_isometry.h"

namespace geodesic::test {
namespace {

// A ball 0.02 above a ground quad (a contact shadow), lit by a sphere light, a quad light and a
// point light, all within 1.5 of the ball; seen from 1.7 away.
Scene lit_ball(const std::string& geometry, uint64_t seed, const std::string& placement = "") {
  Scene scene = scene_from_json(R"({"geometry": ")" + geometry + R"(", )" + placement + R"(
    "camera": {"position": [0, 0.7, 1.5], "look_at": [0, -0.3, 0], "fov_y": 50},
    "materials": {"ground": {"diffuse": 0.6}, "ball": {"diffuse": [0.7, 0.5, 0.3]},
                  "lamp": {"emission": 10}, "panel": {"emission": 4}},
    "objects": [
      {"type": "quad", "material": "ground", "corner": [-1.5, -0.52, -1.5],
       "edge_u": [0, 0, 3], "edge_v": [3, 0, 0]},
      {"type": "sphere", "material": "ball", "center": [0, 0, 0], "radius": 0.5},
      {"type": "sphere", "material": "lamp", "center": [0.9, 1.0, -0.4], "radius": 0.2},
      {"type": "quad", "material": "panel", "corner": [-1.2, 1.0, -0.9],
       "edge_u": [0.5, 0, 0], "edge_v": [0, 0, 0.5]}],
    "lights": [{"type": "point", "position": [-0.5, 1.4, 0.9], "intensity": 4}],
    "render": {"width": 40, "height": 40, "max_depth": 2, "spp": 32}})");
  scene.render.seed = seed;
  return scene;
}

struct Rendered {
  Image image;
  uint32_t non_finite = 0;
};

Rendered render_counted(const Scene& scene) {
  Renderer renderer(device(), scene);
  renderer.add_samples(uint32_t(scene.render.spp));
  return {renderer.image(), renderer.non_finite_samples()};
}

struct Region {
  int x0, y0, x1, y1;
};

struct Case {
  std::string geometry;
  Vec3 offset;  // exponential coordinates of where the origin goes
  Region shadow, lit;  // of the ground: the ball's contact shadow, and in the open
};

constexpr Region kH3Shadow{24, 22, 30, 25}, kH3Lit{2, 28, 9, 32};
constexpr Region kE3Shadow{14, 26, 26, 29}, kE3Lit{1, 33, 8, 39};

class CameraRelative : public ::testing::TestWithParam<Case> {};

TEST_P(CameraRelative, AMovedSceneRendersTheSameImage) {
  const auto& [geometry, offset, shadow, lit] = GetParam();
  const Rendered here = render_counted(lit_ball(geometry, 1));
  const Rendered other_seed = render_counted(lit_ball(geometry, 2));
  const double noise = rms_difference(here.image, other_seed.image);
  ASSERT_GT(mean(here.image).r, 0.02);  // lit

  const Scene at_origin = lit_ball(geometry, 1);
  const GeometryKind k = at_origin.geometry;
  const Mat4 g = model::translation(k, offset) * model::rotation({0.2, 1, 0.4}, 2.0);
  const Rendered far = render_counted(moved_scene(at_origin, g));
  EXPECT_EQ(far.non_finite, 0u);
  EXPECT_EQ(here.non_finite, 0u);
  const double difference = rms_difference(far.image, here.image);
  std::printf("%s moved %g: rms difference %.2e, seed-to-seed noise %.2e\n", geometry.c_str(),
              length(offset), difference, noise);
  EXPECT_LT(difference, noise);
  // The contact shadow is there (and so, by the difference above, far out too).
  const auto green = [&](const Region& r) { return mean(far.image, r.x0, r.y0, r.x1, r.y1).g; };
  std::printf("ground: %.3f in the contact shadow, %.3f in the open\n", green(shadow), green(lit));
  EXPECT_LT(green(shadow), 0.5 * green(lit)) << "contact shadow lost";
}

INSTANTIATE_TEST_SUITE_P(FarFromTheOrigin, CameraRelative,
                         ::testing::Values(Case{"hyperbolic", {4, 0, 0}, kH3Shadow, kH3Lit},
                                           Case{"hyperbolic", {0, 5.6, -5.6}, kH3Shadow, kH3Lit},
                                           Case{"hyperbolic", {-7, 7, 7}, kH3Shadow, kH3Lit},
                                           Case{"hyperbolic", {0, 0, 16}, kH3Shadow, kH3Lit},
                                           Case{"hyperbolic", {-11.5, 11.5, 11.5}, kH3Shadow, kH3Lit},
                                           Case{"euclidean", {1e4, 0, 0}, kE3Shadow, kE3Lit},
                                           Case{"euclidean", {1e6, -1e6, 1e6}, kE3Shadow, kE3Lit}),
                         [](const auto& info) {
                           return info.param.geometry + std::to_string(info.index);
                         });

// The same ball written about its own frame, placed by the document 19.8 units out (the camera
// 20.9; scene-format.md, "Placement"): the loader moves it there and the renderer back, each in
// binary128, and the image is the one at the origin.
TEST(Placement, ASceneTwentyUnitsOutRendersItsImageAtTheOrigin) {
  const std::string placement =
      R"("placement": {"position": [3, -12, 15.5], "rotation": {"yaw": 40, "pitch": -20}},)";
  const Scene placed = lit_ball("hyperbolic", 1, placement);
  const double out = length(model::log_origin(GeometryKind::Hyperbolic,
                                              placed.camera.pose * model::origin()));
  EXPECT_GT(out, 20);
  const Rendered here = render_counted(lit_ball("hyperbolic", 1));
  const Rendered other_seed = render_counted(lit_ball("hyperbolic", 2));
  const Rendered far = render_counted(placed);
  EXPECT_EQ(far.non_finite, 0u);
  const double difference = rms_difference(far.image, here.image);
  const double noise = rms_difference(other_seed.image, here.image);
  std::printf("placed %.2f out: rms difference %.2e, seed-to-seed noise %.2e\n", out, difference,
              noise);
  EXPECT_LT(difference, 0.01 * noise);
}

}  // namespace
}  // namespace geodesic::test
