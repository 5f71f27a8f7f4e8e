// Progressive rendering as the daemon uses it: error estimates from the two halves, new views
// and reduced resolutions.
#include <cmath>

#include "render/relative_error.h"
#include "render_fixture.h"

namespace geodesic::test {
namespace {

Scene small_cornell() {
  Scene scene = paper_model(load_scene_file(source_path("scenes/cornell-box.json")));
  scene.render.width = scene.render.height = 48;
  return scene;
}

TEST(Progressive, EstimatedErrorTracksTheTrueErrorAndFallsAsOneOverRootN) {
  const Scene scene = small_cornell();
  const Image reference = render(scene, 2048);
  Renderer renderer(device(), scene);
  EXPECT_LT(renderer.estimated_error(), 0);  // nothing to compare yet
  renderer.add_samples(8);
  const double e8 = renderer.estimated_error();
  renderer.add_samples(24);
  const double e32 = renderer.estimated_error();
  const double true32 = relative_rmse(renderer.image(), reference);
  EXPECT_NEAR(e32 / e8, 0.5, 0.12);             // 1/sqrt(4)
  EXPECT_NEAR(e32 / true32, 1.0, 0.35);         // an estimate, not a bound
}

TEST(Progressive, ANewViewStartsOverAtTheResolutionAsked) {
  const Scene scene = small_cornell();
  Renderer renderer(device(), scene);
  renderer.add_samples(4);
  const Image before = renderer.image();
  Mat4 pose = scene.camera.pose;
  pose.m[0][3] += 0.3;  // step right
  renderer.set_view(pose, 24, 16);
  EXPECT_EQ(renderer.samples(), 0u);
  renderer.add_samples(2);
  const Image after = renderer.image();
  EXPECT_EQ(after.width, 24);
  EXPECT_EQ(after.height, 16);
  EXPECT_GT(mean(after).r, 0.05);  // a real image, not an empty buffer
  renderer.set_view(scene.camera.pose, 48, 48);
  renderer.add_samples(4);
  EXPECT_LT(rms_difference(renderer.image(), before), 0.2);  // same view, same picture
  EXPECT_THROW(renderer.set_view(pose, 64, 64), std::invalid_argument);
}

}  // namespace
}  // namespace geodesic::test
