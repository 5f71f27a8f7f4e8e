#include "scene/scene_isometry.h"

namespace geodesic {

Scene moved_scene(Scene scene, const WideIsometry& g) {
  const GeometryKind k = scene.geometry;
  const auto move = [&](Vec3& p) { p = model::log_origin(k, g.apply(model::exp_origin(k, p))); };
  for (Sphere& sphere : scene.spheres) move(sphere.center);
  for (TriangleMesh& mesh : scene.meshes) {
    for (Vec3& p : mesh.positions) move(p);
    if (k == GeometryKind::Euclidean)
      for (Vec3& n : mesh.normals) n = (g.matrix() * Vec4{n.x, n.y, n.z, 0}).xyz();
  }
  for (PointLight& light : scene.lights) move(light.position);
  for (Shape& shape : scene.shapes) {  // model vectors, carried linearly (scene.h ShapeParams)
    shape.params.a = g.matrix() * shape.params.a;
    shape.params.b = g.matrix() * shape.params.b;
  }
  scene.camera.pose = g.apply(scene.camera.pose);
  return scene;
}

Scene moved_scene(Scene scene, const Mat4& g) {
  const GeometryKind k = scene.geometry;
  return moved_scene(std::move(scene), WideIsometry(k, g));
}

}  // namespace geodesic
