#include "render/packed_scene.h"

namespace geodesic {
namespace {

std::array<float, 4> to_float4(const Vec3& v, double w = 0) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z),
          static_cast<float>(w)};
}

}  // namespace

PackedScene pack_scene(const Scene& scene) {
  PackedScene out;
  for (const Material& m : scene.materials)
    out.materials.push_back({to_float4(m.ambient), to_float4(m.diffuse),
                             to_float4(m.specular, m.shininess), to_float4(m.mirror),
                             to_float4(m.emission)});

  for (const Sphere& s : scene.spheres) {
    out.spheres.push_back({to_float4(s.center, s.radius), s.material, {0, 0, 0}});
    // Pad the box by a relative epsilon so float rounding never clips the silhouette.
    float r = static_cast<float>(s.radius * (1 + 1e-5));
    GpuAabb box{};
    for (int i = 0; i < 3; ++i) {
      box.min[i] = static_cast<float>(s.center[i]) - r;
      box.max[i] = static_cast<float>(s.center[i]) + r;
    }
    out.sphere_bounds.push_back(box);
  }

  for (const PointLight& l : scene.lights)
    out.lights.push_back({to_float4(l.position, 1), to_float4(l.intensity)});

  for (const TriangleMesh& mesh : scene.meshes) {
    const auto base = static_cast<uint32_t>(out.positions.size());
    const bool smooth = mesh.normals.size() == mesh.positions.size();
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      out.positions.push_back(to_float4(mesh.positions[i], 1));
      out.normals.push_back(smooth ? to_float4(mesh.normals[i]) : std::array<float, 4>{});
    }
    for (uint32_t index : mesh.indices) out.indices.push_back(base + index);
    for (size_t t = 0; t < mesh.indices.size() / 3; ++t)
      out.triangles.push_back({mesh.material, smooth ? 1u : 0u});
  }
  return out;
}

}  // namespace geodesic
