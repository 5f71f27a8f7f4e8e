#include "scene/scene_isometry.h"

namespace geodesic {

Scene moved_scene(Scene scene, const Mat4& g) {
  const GeometryKind k = scene.geometry;
  const auto move = [&](Vec3& p) {
    p = model::log_origin(k, model::normalize_point(k, g * model::exp_origin(k, p)));
  };
  for (Sphere& sphere : scene.spheres) move(sphere.center);
  for (TriangleMesh& mesh : scene.meshes) {
    for (Vec3& p : mesh.positions) move(p);
    if (k == GeometryKind::Euclidean)
      for (Vec3& n : mesh.normals) n = (g * Vec4{n.x, n.y, n.z, 0}).xyz();
  }
  for (PointLight& light : scene.lights) move(light.position);
  scene.camera.pose = model::reorthonormalize(k, g * scene.camera.pose);
  return scene;
}

}  // namespace geodesic
