// The bundled Cornell box (the paper's figure): what a viewer must see in it.
#include <cmath>
#include <numbers>

#include "render_fixture.h"

namespace geodesic::test {
namespace {

constexpr int kSize = 128;

Scene cornell(int size = kSize) {
  Scene scene = paper_model(load_scene_file(source_path("scenes/cornell-box.json")));
  scene.render.width = scene.render.height = size;
  return scene;
}

// Pixel where the scene's pinhole camera sees world point p.
std::pair<int, int> project(const Scene& scene, const Vec3& p) {
  const Mat4& pose = scene.camera.pose;
  const Vec3 position{pose.m[0][3], pose.m[1][3], pose.m[2][3]};
  const Vec3 d = p - position;
  const Vec3 right{pose.m[0][0], pose.m[1][0], pose.m[2][0]};
  const Vec3 up{pose.m[0][1], pose.m[1][1], pose.m[2][1]};
  const Vec3 back{pose.m[0][2], pose.m[1][2], pose.m[2][2]};
  const double t = std::tan(scene.camera.fov_y_degrees * std::numbers::pi / 360);
  const double depth = -dot(d, back);
  const double aspect = double(scene.render.width) / scene.render.height;
  const double ndc_x = dot(d, right) / depth / (t * aspect);
  const double ndc_y = dot(d, up) / depth / t;
  return {int((ndc_x + 1) / 2 * scene.render.width), int((1 - ndc_y) / 2 * scene.render.height)};
}

Rgb block(const Image& image, std::pair<int, int> centre, int half = 1) {
  return mean(image, centre.first - half, centre.second - half, centre.first + half + 1,
              centre.second + half + 1);
}

class CornellBox : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(cornell());
    image_ = new Image(render(*scene_, 64));
  }
  static void TearDownTestSuite() {
    delete image_;
    delete scene_;
  }
  static Scene* scene_;
  static Image* image_;
};
Scene* CornellBox::scene_ = nullptr;
Image* CornellBox::image_ = nullptr;

TEST_F(CornellBox, LeftWallIsRedAndRightWallIsGreen) {
  const Rgb left = block(*image_, project(*scene_, {-1, 0.2, -0.5}), 3);
  const Rgb right = block(*image_, project(*scene_, {1, 0.2, -0.5}), 3);
  EXPECT_GT(left.r, 2 * left.g);
  EXPECT_GT(left.r, 2 * left.b);
  EXPECT_GT(right.g, 2 * right.r);
  EXPECT_GT(right.g, 2 * right.b);
}

TEST_F(CornellBox, WindowShowsTheDarkOutside) {
  // Looking up through the ceiling's window the camera sees nothing: black.
  const Rgb window = block(*image_, project(*scene_, {0, 1, 0}), 1);
  const Rgb ceiling = block(*image_, project(*scene_, {0, 1, -0.65}), 1);
  EXPECT_LT(window.r + window.g + window.b, 1e-6);
  EXPECT_GT(ceiling.r, 0.05);
}

TEST_F(CornellBox, MirrorSphereReflectsTheGreenWall) {
  // The mirror sphere's upper right flank faces +x+y: the camera ray reflected there goes up
  // and right, over the blue sphere, to the green wall.
  const Sphere& mirror = scene_->spheres.at(0);
  const Vec3 flank = mirror.center + mirror.radius * normalize(Vec3{1, 1, 1});
  const Rgb seen = block(*image_, project(*scene_, flank), 1);
  EXPECT_GT(seen.g, 1.5 * seen.r);
  EXPECT_GT(seen.g, 1.5 * seen.b);
}

TEST_F(CornellBox, FloorInASphereShadowIsDarkerThanLitFloor) {
  // The light is above the window at the centre: the floor right under the front sphere's
  // centre is in its shadow; the floor at the box's front-left corner is lit.
  const Sphere& front = scene_->spheres.at(2);
  const Rgb shadow = block(*image_, project(*scene_, {front.center.x, -1, front.center.z + 0.1}), 1);
  const Rgb lit = block(*image_, project(*scene_, {-0.1, -1, 0.8}), 1);
  EXPECT_LT(shadow.r + shadow.g + shadow.b, 0.5 * (lit.r + lit.g + lit.b));
}

TEST(CornellBoxConvergence, TwiceTheSamplesIsCloserToTheConvergedImage) {
  const Scene scene = cornell(48);
  const Image reference = render(scene, 1024);
  Renderer renderer(device(), scene);
  renderer.add_samples(8);
  const double error_n = rms_difference(renderer.image(), reference);
  renderer.add_samples(8);
  const double error_2n = rms_difference(renderer.image(), reference);
  EXPECT_LT(error_2n, error_n);
  // Monte Carlo error falls as 1/sqrt(n): expect about 0.71, allow for noise in the estimate.
  EXPECT_NEAR(error_2n / error_n, std::sqrt(0.5), 0.12);
}

TEST(CornellBoxBackends, RayQueryAndPipelineRenderTheSameImage) {
  const Scene scene = cornell(48);
  const Image a = render(scene, 16, BackendKind::RayQuery);
  const Image b = render(scene, 16, BackendKind::RayTracingPipeline);
  const Rgb ma = mean(a), mb = mean(b);
  EXPECT_NEAR(ma.r, mb.r, 0.01 * ma.r);
  EXPECT_NEAR(ma.g, mb.g, 0.01 * ma.g);
  // Same random streams and the same GLSL: images agree to float round-off almost everywhere.
  EXPECT_LT(rms_difference(a, b), 0.01);
}

}  // namespace
}  // namespace geodesic::test
