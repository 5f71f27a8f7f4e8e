// A Vulkan buffer with its own host-visible memory: simple, and on lavapipe (where all memory
// is host memory) also the fastest. Move-only; freed with its owner.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <vector>

#include "render/device/vulkan_context.h"

namespace geodesic {

class GpuBuffer {
 public:
  GpuBuffer() = default;
  GpuBuffer(VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage);
  ~GpuBuffer();
  GpuBuffer(GpuBuffer&& other) noexcept;
  GpuBuffer& operator=(GpuBuffer&& other) noexcept;
  GpuBuffer(const GpuBuffer&) = delete;
  GpuBuffer& operator=(const GpuBuffer&) = delete;

  // A buffer holding a copy of `data` (at least one element's worth of storage, since Vulkan
  // forbids empty buffers).
  template <typename T>
  static GpuBuffer from_vector(VulkanContext& ctx, const std::vector<T>& data,
                              VkBufferUsageFlags usage) {
    GpuBuffer b(ctx, std::max<VkDeviceSize>(sizeof(T), data.size() * sizeof(T)), usage);
    if (!data.empty()) std::memcpy(b.mapped(), data.data(), data.size() * sizeof(T));
    return b;
  }

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  VkDeviceAddress address() const { return address_; }
  void* mapped() const { return mapped_; }

 private:
  void release();

  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  VkDeviceAddress address_ = 0;
  void* mapped_ = nullptr;
};

}  // namespace geodesic
