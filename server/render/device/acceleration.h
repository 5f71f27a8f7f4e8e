// Acceleration structures: per cell of the chart atlas, one bottom level for its triangles,
// one for its spheres' bounding boxes and one for its shapes' (scene/shape.h), all in the
// cell's chart; a top level with an instance of each that exists. The instance mask is the
// cell's bit (rays trace one cell at a time), the custom index the offset of the cell's first
// triangle, sphere ref or shape ref, and the shader-binding-table offset the kind
// (HIT_RECORD_*, common/gpu_types.h).
#pragma once

#include "render/device/gpu_buffer.h"
#include "render/prepare/packed_scene.h"

#include <vector>

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
  GpuBuffer shape_bounds;
  GpuBuffer instances;
  std::vector<AccelerationStructure> bottom;
  AccelerationStructure top;

  // Without sphere (shape) boxes where the shaders test each cell's spheres (shapes) one by
  // one beside the traversal (PipelineFeatures::traced_spheres, traced_shapes).
  static SceneAccelerationStructures build(VulkanContext& ctx, const PackedScene& scene,
                                           bool sphere_boxes = true, bool shape_boxes = true);
};

}  // namespace geodesic
