#include "render/device/acceleration.h"

#include <utility>
#include <vector>

namespace geodesic {
namespace {

constexpr VkBufferUsageFlags kBuildInput =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

VkDeviceSize align_up(VkDeviceSize value, VkDeviceSize alignment) {
  return alignment ? (value + alignment - 1) / alignment * alignment : value;
}

VkAccelerationStructureInstanceKHR instance_of(const AccelerationStructure& blas,
                                               uint32_t custom_index, uint8_t mask,
                                               uint32_t binding_table_offset) {
  VkAccelerationStructureInstanceKHR instance{};
  instance.transform.matrix[0][0] = instance.transform.matrix[1][1] =
      instance.transform.matrix[2][2] = 1.0f;
  instance.instanceCustomIndex = custom_index;
  instance.mask = mask;
  instance.instanceShaderBindingTableRecordOffset = binding_table_offset;
  instance.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
  instance.accelerationStructureReference = blas.address();
  return instance;
}

}  // namespace

AccelerationStructure AccelerationStructure::build(
    VulkanContext& ctx, VkAccelerationStructureTypeKHR type,
    const VkAccelerationStructureGeometryKHR& geometry, uint32_t primitive_count) {
  VkAccelerationStructureBuildGeometryInfoKHR info{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  info.type = type;
  info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
  info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  info.geometryCount = 1;
  info.pGeometries = &geometry;

  VkAccelerationStructureBuildSizesInfoKHR sizes{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  ctx.rt().get_build_sizes(ctx.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info,
                           &primitive_count, &sizes);

  AccelerationStructure as;
  as.ctx_ = &ctx;
  as.storage_ = GpuBuffer(ctx, sizes.accelerationStructureSize,
                          VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR);
  VkAccelerationStructureCreateInfoKHR create{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  create.buffer = as.storage_.handle();
  create.size = sizes.accelerationStructureSize;
  create.type = type;
  vk_check(ctx.rt().create_acceleration_structure(ctx.device(), &create, nullptr, &as.handle_),
           "vkCreateAccelerationStructureKHR");

  const VkDeviceSize scratch_alignment =
      ctx.acceleration_properties().minAccelerationStructureScratchOffsetAlignment;
  GpuBuffer scratch(ctx, sizes.buildScratchSize + scratch_alignment,
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  info.dstAccelerationStructure = as.handle_;
  info.scratchData.deviceAddress = align_up(scratch.address(), scratch_alignment);

  VkAccelerationStructureBuildRangeInfoKHR range{};
  range.primitiveCount = primitive_count;
  const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    ctx.rt().cmd_build_acceleration_structures(cmd, 1, &info, &ranges);
  });

  VkAccelerationStructureDeviceAddressInfoKHR address{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  address.accelerationStructure = as.handle_;
  as.address_ = ctx.rt().get_acceleration_structure_address(ctx.device(), &address);
  return as;
}

AccelerationStructure::~AccelerationStructure() { release(); }

AccelerationStructure::AccelerationStructure(AccelerationStructure&& other) noexcept {
  *this = std::move(other);
}

AccelerationStructure& AccelerationStructure::operator=(AccelerationStructure&& other) noexcept {
  if (this != &other) {
    release();
    ctx_ = std::exchange(other.ctx_, nullptr);
    handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
    address_ = std::exchange(other.address_, 0);
    storage_ = std::move(other.storage_);
  }
  return *this;
}

void AccelerationStructure::release() {
  if (ctx_ && handle_)
    ctx_->rt().destroy_acceleration_structure(ctx_->device(), handle_, nullptr);
  handle_ = VK_NULL_HANDLE;
  ctx_ = nullptr;
}

SceneAccelerationStructures SceneAccelerationStructures::build(VulkanContext& ctx,
                                                               const PackedScene& scene,
                                                               bool sphere_boxes,
                                                               bool shape_boxes) {
  SceneAccelerationStructures out;
  std::vector<VkAccelerationStructureInstanceKHR> instances;
  out.positions = GpuBuffer::from_vector(ctx, scene.positions, kBuildInput);
  out.indices = GpuBuffer::from_vector(ctx, scene.indices, kBuildInput);
  out.sphere_bounds = GpuBuffer::from_vector(ctx, scene.sphere_bounds, kBuildInput);
  out.shape_bounds = GpuBuffer::from_vector(ctx, scene.shape_bounds, kBuildInput);

  for (uint32_t c = 0; c < scene.cell_geometry.size(); ++c) {
    const CellGeometry& cell = scene.cell_geometry[c];
    // One mask bit per cell; past eight cells they share bits and the shaders check the cell
    // of each candidate (SHARED_CELL_MASKS).
    const uint8_t mask = uint8_t(1u << (c % 8));
    if (cell.triangle_count > 0) {
      VkAccelerationStructureGeometryKHR geometry{
          VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
      geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
      geometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
      auto& tri = geometry.geometry.triangles;
      tri.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
      tri.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
      tri.vertexData.deviceAddress = out.positions.address();
      tri.vertexStride = sizeof(float) * 4;
      tri.maxVertex = static_cast<uint32_t>(scene.positions.size() - 1);
      tri.indexType = VK_INDEX_TYPE_UINT32;
      tri.indexData.deviceAddress =
          out.indices.address() + VkDeviceSize(cell.first_triangle) * 3 * sizeof(uint32_t);
      out.bottom.push_back(AccelerationStructure::build(
          ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, geometry, cell.triangle_count));
      instances.push_back(instance_of(out.bottom.back(), cell.first_triangle, mask,
                                        HIT_RECORD_TRIANGLES));
    }
    // The cell's boxes of one procedural kind (spheres, shapes: refs [first, first + count)),
    // in an instance whose hit record selects the kind's intersection shader.
    const auto add_boxes = [&](const GpuBuffer& bounds, uint32_t first, uint32_t count,
                               uint32_t record) {
      if (count == 0) return;
      VkAccelerationStructureGeometryKHR geometry{
          VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
      geometry.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
      geometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
      auto& aabbs = geometry.geometry.aabbs;
      aabbs.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
      aabbs.data.deviceAddress = bounds.address() + VkDeviceSize(first) * sizeof(GpuAabb);
      aabbs.stride = sizeof(GpuAabb);
      out.bottom.push_back(AccelerationStructure::build(
          ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, geometry, count));
      instances.push_back(instance_of(out.bottom.back(), first, mask, record));
    };
    if (sphere_boxes)
      add_boxes(out.sphere_bounds, cell.first_sphere_ref, cell.sphere_ref_count,
                HIT_RECORD_SPHERES);
    if (shape_boxes)
      add_boxes(out.shape_bounds, cell.first_shape_ref, cell.shape_ref_count, HIT_RECORD_SHAPES);
  }

  out.instances = GpuBuffer::from_vector(ctx, instances, kBuildInput);
  VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geometry.geometry.instances.sType =
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  geometry.geometry.instances.data.deviceAddress = out.instances.address();
  out.top = AccelerationStructure::build(ctx, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                                         geometry, static_cast<uint32_t>(instances.size()));
  return out;
}

}  // namespace geodesic
