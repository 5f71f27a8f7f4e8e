// A compute pipeline whose bindings 0 … n−1 are storage buffers and whose one push-constant
// block is a few bytes: the shape of the test probes (tests/render/probe_runner.h) and of
// bench/float64_cost. The renderer's own entry points use the scene layout instead
// (render/device/scene_layout.h).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>

#include "render/device/gpu_buffer.h"
#include "render/device/vulkan_context.h"

namespace geodesic {

class StorageKernel {
 public:
  StorageKernel(VulkanContext& ctx, std::span<const uint32_t> spirv, uint32_t buffers,
                uint32_t push_bytes);
  ~StorageKernel();
  StorageKernel(const StorageKernel&) = delete;
  StorageKernel& operator=(const StorageKernel&) = delete;

  // Points bindings 0, 1, … at these buffers, whole. Call it between dispatches, not during one.
  void bind(std::initializer_list<const GpuBuffer*> buffers);

  // Records the dispatch of `groups` workgroups with `push` (push_bytes of it) as the push
  // constants, then a barrier that makes the shader's writes visible to the host.
  void record(VkCommandBuffer cmd, const void* push, uint32_t groups) const;

 private:
  void create(std::span<const uint32_t> spirv);
  void release();

  VulkanContext& ctx_;
  uint32_t buffers_;
  uint32_t push_bytes_;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace geodesic
