// moved_scene (scene/scene_isometry.h): a scene moved by an isometry keeps every distance and
// every angle its camera sees, and moving it back gives the scene again, in E3, H3 and S3.
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

}  // namespace
}  // namespace geodesic::test
