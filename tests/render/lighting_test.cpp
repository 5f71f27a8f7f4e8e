// Local illumination (the paper's eq. 2.2) and mirrors, checked against closed forms.
#include <cmath>

#include "render_fixture.h"

namespace geodesic::test {
namespace {

// A white floor lit by a point light straight above, a sphere casting a shadow, no bounces:
// lit floor = k_a L_a + k_d I cos(theta); shadowed floor = k_a L_a.
TEST(Lighting, PointLightAndShadowMatchEquationTwoPointTwo) {
  const Scene scene = scene_from_json(R"({
    "geometry": "euclidean",
    "camera": {"position": [0, 6, 0.001], "look_at": [0, 0, 0], "fov_y": 60},
    "materials": {"floor": {"ambient": 0.5, "diffuse": 0.6}, "ball": {"diffuse": 0.5}},
    "objects": [
      {"type": "quad", "corner": [-4, 0, 4], "edge_u": [8, 0, 0], "edge_v": [0, 0, -8], "material": "floor"},
      {"type": "sphere", "center": [0, 1, 0], "radius": 0.5, "material": "ball"}],
    "lights": [{"type": "point", "position": [0, 3, 0], "intensity": 2}],
    "render": {"width": 64, "height": 64, "max_depth": 0, "ambient": 0.1, "lighting": "paper"}
  })");
  const Image image = render(scene, 4);
  // Floor point (2, 0, 0): the light is at distance sqrt(13), cos(theta) = 3 / sqrt(13).
  // The camera (fov 60, height 6) sees x = 2 at ndc 2 / (6 tan 30deg) = 0.577.
  const int lit_x = int((0.57735 + 1) / 2 * 64);
  const double expected_lit = 0.5 * 0.1 + 0.6 * 2 * 3 / std::sqrt(13.0);
  EXPECT_NEAR(image.at(lit_x, 32, 0), expected_lit, 0.03 * expected_lit);
  // Floor straight under the sphere's edge is shadowed: only the ambient term remains. The
  // sphere hides the floor below it, so look just outside its silhouette, at r = 0.6 on the
  // floor, which the sphere (radius 0.5 at height 1, light at height 3) still shadows.
  const int shadow_x = int((0.6 / (6 * 0.57735) + 1) / 2 * 64) + 1;
  EXPECT_NEAR(image.at(shadow_x, 32, 0), 0.05, 0.005);
}

// Looking straight at a mirror sphere with an emitter behind the camera: the centre of the
// sphere reflects the emitter, scaled by the mirror reflectance.
TEST(Lighting, MirrorReflectsWhatIsBehindTheCamera) {
  const Scene scene = scene_from_json(R"({
    "geometry": "euclidean",
    "camera": {"position": [0, 0, 3], "look_at": [0, 0, 0], "fov_y": 20},
    "materials": {"chrome": {"mirror": [0.9, 0.8, 0.7]}, "glow": {"emission": [0.2, 1.0, 0.3]}},
    "objects": [
      {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "chrome"},
      {"type": "quad", "corner": [-10, -10, 6], "edge_u": [20, 0, 0], "edge_v": [0, 20, 0], "material": "glow"}],
    "render": {"width": 32, "height": 32, "max_depth": 2, "lighting": "paper"}
  })");
  const Image image = render(scene, 2);
  const Rgb centre = mean(image, 14, 14, 18, 18);
  EXPECT_NEAR(centre.r, 0.9 * 0.2, 1e-4);
  EXPECT_NEAR(centre.g, 0.8 * 1.0, 1e-4);
  EXPECT_NEAR(centre.b, 0.7 * 0.3, 1e-4);
}

}  // namespace
}  // namespace geodesic::test
