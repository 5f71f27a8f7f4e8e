// Acceleration structures: one bottom level for all triangles, one for all sphere bounding
// boxes, and a top level with an instance of each that exists. Instance custom index and
// shader-binding-table offset tell the kinds apart (0 = triangles, 1 = spheres).
#pragma once

#include "render/gpu_buffer.h"
#include "render/packed_scene.h"

namespace geodesic {

class AccelerationStructure {
 public:
  AccelerationStructure() = default;
  ~AccelerationStructure();
  AccelerationStructure(AccelerationStructure&& other) noexcept;
  AccelerationStructure& operator=(AccelerationStructure&& other) noexcept;

  VkAccelerationStructureKHR handle() const { return handle_; }
  VkDeviceAddress address() const { return address_; }

  // Builds from one geometry description (bottom or top level) and waits for completion.
  static AccelerationStructure build(VulkanContext& ctx, VkAccelerationStructureTypeKHR type,
                                     const VkAccelerationStructureGeometryKHR& geometry,
                                     uint32_t primitive_count);

 private:
  void release();

  const VulkanContext* ctx_ = nullptr;
  VkAccelerationStructureKHR handle_ = VK_NULL_HANDLE;
  VkDeviceAddress address_ = 0;
  GpuBuffer storage_;
};

// Everything the shaders trace against, kept alive together.
struct SceneAccelerationStructures {
  GpuBuffer positions;
  GpuBuffer indices;
  GpuBuffer sphere_bounds;
  GpuBuffer instances;
  AccelerationStructure triangles;
  AccelerationStructure spheres;
  AccelerationStructure top;

  static SceneAccelerationStructures build(VulkanContext& ctx, const PackedScene& scene);
};

}  // namespace geodesic
