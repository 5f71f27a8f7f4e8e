// The scene flattened into the arrays the shaders read (layouts match
// shaders/common/scene_data.glsl, std430). Pure data: built and tested without a device.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace geodesic {

struct GpuMaterial {
  std::array<float, 4> ambient;   // rgb
  std::array<float, 4> diffuse;   // rgb
  std::array<float, 4> specular;  // rgb, w = shininess k_e
  std::array<float, 4> mirror;    // rgb
  std::array<float, 4> emission;  // rgb
};

struct GpuSphere {
  std::array<float, 4> center_radius;
  uint32_t material;
  uint32_t padding[3];
};

struct GpuPointLight {
  std::array<float, 4> position;
  std::array<float, 4> intensity;
};

struct GpuTriangle {
  uint32_t material;
  uint32_t smooth;  // 1 when the mesh supplies per-vertex normals
};

struct GpuAabb {
  float min[3];
  float max[3];
};

struct PackedScene {
  std::vector<GpuMaterial> materials;
  std::vector<GpuSphere> spheres;
  std::vector<GpuAabb> sphere_bounds;
  std::vector<GpuPointLight> lights;
  std::vector<std::array<float, 4>> positions;  // all meshes' vertices, w = 1
  std::vector<std::array<float, 4>> normals;    // one per position (zero when flat)
  std::vector<uint32_t> indices;                // three per triangle, into positions
  std::vector<GpuTriangle> triangles;

  uint32_t triangle_count() const { return static_cast<uint32_t>(triangles.size()); }
};

PackedScene pack_scene(const Scene& scene);

}  // namespace geodesic
