// moved_scene (scene/scene_isometry.h): a scene moved by an isometry keeps every distance and
// every angle its camera sees, and moving it back gives the scene again, in E3, H3 and S3; in H3
// 20 units out, seen from its own camera as the renderer sees it (geometry/wide_isometry.h).
#include <gtest/gtest.h>

#include "scene/scene_isometry.h"

namespace geodesic::test {
namespace {

Scene sample_scene(GeometryKind k) {
  Scene scene;
  scene.geometry = k;
  scene.spheres = {{{0.3, -0.2, 0.1}, 0.2, 0}, {{-0.5, 0.4, 0.6}, 0.1, 0}};
  scene.meshes.push_back({{{0.1, 0, 0}, {0, 0.7, 0}, {0, 0, -0.4}}, {}, {0, 1, 2}, 0});
  if (k == GeometryKind::Euclidean)
    scene.meshes[0].normals = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  scene.lights = {{{0.2, 0.9, -0.3}, {1, 1, 1}}};
  scene.camera.pose = model::translation(k, {0.1, 0.2, 1.2}) * model::rotation({0, 1, 0}, 0.3);
  return scene;
}

std::vector<Vec4> points(const Scene& scene) {
  const GeometryKind k = scene.geometry;
  std::vector<Vec4> out{scene.camera.pose * model::origin()};
  for (const Sphere& s : scene.spheres) out.push_back(model::exp_origin(k, s.center));
  for (const Vec3& p : scene.meshes[0].positions) out.push_back(model::exp_origin(k, p));
  for (const PointLight& l : scene.lights) out.push_back(model::exp_origin(k, l.position));
  return out;
}

struct Case {
  GeometryKind kind;
  double distance;  // how far the scene is moved
};

class MovedScene : public ::testing::TestWithParam<Case> {};

TEST_P(MovedScene, KeepsDistancesAndComesBack) {
  const auto [k, distance] = GetParam();
  const Scene scene = sample_scene(k);
  const Mat4 g = model::translation(k, distance * normalize(Vec3{1, -2, 0.5})) *
                 model::rotation({0.3, 1, -0.2}, 1.1);
  const Scene moved = moved_scene(scene, g);
  const std::vector<Vec4> before = points(scene), after = points(moved);
  // H3: the moved coordinates are ~e^D / 2, so a distance between two of them is good to
  // about u e^(2D) (docs/numerics.md).
  const double tolerance = 1e-12 * (k == GeometryKind::Hyperbolic ? std::exp(2 * distance) : 1 + distance);
  for (size_t i = 0; i < before.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      EXPECT_NEAR(model::geodesic_distance(k, after[i], after[j]),
                  model::geodesic_distance(k, before[i], before[j]), tolerance)
          << i << ", " << j;
  // What the camera sees: every point in the camera's frame is where it was.
  const Mat4 view = model::inverse_isometry(k, scene.camera.pose);
  const Mat4 moved_view = model::inverse_isometry(k, moved.camera.pose);
  for (size_t i = 1; i < before.size(); ++i) {
    const Vec4 a = view * before[i], b = moved_view * after[i];
    EXPECT_NEAR(length(a.xyz() - b.xyz()), 0, tolerance) << i;
    EXPECT_NEAR(a.w, b.w, tolerance) << i;
  }
  if (k == GeometryKind::Euclidean)  // normals turn with the scene
    for (size_t i = 0; i < 3; ++i) {
      const Vec3 n = moved.meshes[0].normals[i];
      const Vec4 expect = g * Vec4{scene.meshes[0].normals[i].x, scene.meshes[0].normals[i].y,
                                   scene.meshes[0].normals[i].z, 0};
      EXPECT_NEAR(length(n - expect.xyz()), 0, 1e-12);
    }
  // And back.
  const Scene back = moved_scene(moved, model::inverse_isometry(k, g));
  for (size_t s = 0; s < scene.spheres.size(); ++s)
    EXPECT_NEAR(length(back.spheres[s].center - scene.spheres[s].center), 0, tolerance);
  EXPECT_LT(model::isometry_error(k, moved.camera.pose), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Geometries, MovedScene,
                         ::testing::Values(Case{GeometryKind::Euclidean, 1e6},
                                           Case{GeometryKind::Euclidean, 3},
                                           Case{GeometryKind::Hyperbolic, 0.5},
                                           Case{GeometryKind::Hyperbolic, 6},
                                           Case{GeometryKind::Spherical, 2.5}));

// The scene seen from its camera, as the renderer moves it (render/device/renderer.cpp): exponential
// coordinates of every point in the camera's frame.
std::vector<Vec3> seen_from_camera(const Scene& scene) {
  const Scene seen = moved_scene(scene, WideIsometry(scene.geometry, scene.camera.pose).inverse());
  std::vector<Vec3> out;
  for (const Vec4& p : points(seen)) out.push_back(model::log_origin(scene.geometry, p));
  return out;
}

class FarOut : public ::testing::TestWithParam<double> {};

// H3 D out: the scene's coordinates are ~e^D / 2 and rounded to double there, and composing in
// double would cancel products of e^(2D). Seen from its camera, every point is where it was
// within 1e-7 (float resolves 6e-8), up to D = 20 (e^40 = 2.4e17).
TEST_P(FarOut, TheCameraSeesTheSceneItSawAtTheOrigin) {
  const double distance = GetParam();
  const GeometryKind k = GeometryKind::Hyperbolic;
  const Scene scene = sample_scene(k);
  const Mat4 g = model::translation(k, distance * normalize(Vec3{1, -2, 0.5})) *
                 model::rotation({0.3, 1, -0.2}, 1.1);
  const Scene moved = moved_scene(scene, g);
  const Vec4 camera = moved.camera.pose * model::origin();
  EXPECT_GT(length(model::log_origin(k, camera)), distance - 1.5);  // it did go far out
  EXPECT_LT(model::relative_isometry_error(k, moved.camera.pose), 1e-14);

  const std::vector<Vec3> before = seen_from_camera(scene), after = seen_from_camera(moved);
  double worst = 0;
  for (size_t i = 0; i < before.size(); ++i) worst = std::max(worst, length(after[i] - before[i]));
  EXPECT_LT(worst, 1e-7) << "moved " << distance;

  // The regime is hard: in double, the camera's inverse times a point loses them (from D ~ 12).
  const Mat4 view = model::inverse_isometry(k, moved.camera.pose);
  double naive = 0;
  const std::vector<Vec4> far = points(moved);
  for (size_t i = 1; i < far.size(); ++i)
    naive = std::max(naive, length(model::log_origin(k, model::normalize_point(k, view * far[i])) -
                                   before[i]));
  std::printf("moved %g: worst %.1e in binary128, %.1e in double\n", distance, worst, naive);
  if (distance >= 16) EXPECT_GT(naive, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Hyperbolic, FarOut, ::testing::Values(8.0, 12.0, 16.0, 20.0));

}  // namespace
}  // namespace geodesic::test
