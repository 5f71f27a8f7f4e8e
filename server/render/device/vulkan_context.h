// The headless Vulkan device: instance, the chosen ray-tracing capable physical device, one
// compute queue, and the extension entry points the loader does not export. Submissions may come
// from several threads at once: each records into its own command pool and waits on its own
// fence, and only the queue submission itself is serialised, so a renderer can be built (its
// acceleration structures uploaded) while another renders.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "render/device/vk_check.h"

namespace geodesic {

// What `geodesic devices` prints and device selection decides on.
struct DeviceDescription {
  uint32_t index = 0;
  std::string name;
  std::string type;  // "cpu", "discrete-gpu", ...
  std::string driver;
  bool cpu = false;
  bool acceleration_structure = false;
  bool ray_tracing_pipeline = false;
  bool ray_query = false;
  bool float64 = false;  // shaderFloat64
  bool primitive_culling = false;  // rayTraversalPrimitiveCulling: SKIP_AABBS / SKIP_TRIANGLES
  std::vector<std::string> missing;  // required extensions/features it lacks

  bool can_ray_trace() const { return missing.empty() && (ray_tracing_pipeline || ray_query); }
};

// Extension entry points fetched with vkGetDeviceProcAddr.
struct RayTracingFunctions {
  PFN_vkGetAccelerationStructureBuildSizesKHR get_build_sizes = nullptr;
  PFN_vkCreateAccelerationStructureKHR create_acceleration_structure = nullptr;
  PFN_vkDestroyAccelerationStructureKHR destroy_acceleration_structure = nullptr;
  PFN_vkCmdBuildAccelerationStructuresKHR cmd_build_acceleration_structures = nullptr;
  PFN_vkGetAccelerationStructureDeviceAddressKHR get_acceleration_structure_address = nullptr;
  PFN_vkCreateRayTracingPipelinesKHR create_ray_tracing_pipelines = nullptr;
  PFN_vkGetRayTracingShaderGroupHandlesKHR get_shader_group_handles = nullptr;
  PFN_vkCmdTraceRaysKHR cmd_trace_rays = nullptr;
};

class PipelineCache;

class VulkanContext {
 public:
  // selector: empty (prefer a GPU that can ray-trace, else lavapipe), a device index, or a
  // case-insensitive substring of the device name (e.g. "llvmpipe", "lavapipe", "nvidia").
  explicit VulkanContext(const std::string& selector = "");
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  static std::vector<DeviceDescription> list_devices();

  VkDevice device() const { return device_; }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkQueue queue() const { return queue_; }
  const DeviceDescription& description() const { return description_; }
  const RayTracingFunctions& rt() const { return rt_; }
  const VkPhysicalDeviceRayTracingPipelinePropertiesKHR& pipeline_properties() const {
    return pipeline_properties_;
  }
  const VkPhysicalDeviceAccelerationStructurePropertiesKHR& acceleration_properties() const {
    return acceleration_properties_;
  }

  // The pipelines built on this device (render/device/pipeline_cache.h).
  PipelineCache& pipeline_cache() { return *pipeline_cache_; }

  uint32_t find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags wanted) const;

  // True once a submission came back VK_ERROR_DEVICE_LOST: the device is gone for good (its
  // objects may only be destroyed) and every later submission fails the same way.
  bool lost() const { return lost_; }

  // Records commands into a fresh command buffer, submits and waits for completion. Thread-safe.
  template <typename Record>
  void submit_and_wait(Record&& record) {
    OneShot shot(device_, queue_family_);
    record(shot.cmd);
    submit(shot);
  }

 private:
  // A command buffer with its own transient pool and fence: one submission's, on any thread.
  struct OneShot {
    OneShot(VkDevice device, uint32_t queue_family);
    ~OneShot();
    OneShot(const OneShot&) = delete;
    OneShot& operator=(const OneShot&) = delete;
    void release();
    VkDevice device;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
  };
  void submit(OneShot& shot);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  std::mutex queue_mutex_;  // vkQueueSubmit: the queue is externally synchronised
  std::atomic<bool> lost_{false};
  DeviceDescription description_;
  RayTracingFunctions rt_;
  VkPhysicalDeviceMemoryProperties memory_properties_{};
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR pipeline_properties_{};
  VkPhysicalDeviceAccelerationStructurePropertiesKHR acceleration_properties_{};
  std::unique_ptr<PipelineCache> pipeline_cache_;
};

}  // namespace geodesic
