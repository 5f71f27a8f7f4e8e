// Vulkan failures as exceptions: the one error type of the device layer, apart from the device
// itself, so that what only checks results (the pipeline cache, buffers) need not include the
// device (render/device/vulkan_context.h), which owns the pipeline cache.
#pragma once

#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

namespace geodesic {

class VulkanError : public std::runtime_error {
 public:
  explicit VulkanError(const std::string& message, VkResult result = VK_ERROR_UNKNOWN)
      : std::runtime_error(message), result_(result) {}
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

// Throws VulkanError naming the call and the result when a Vulkan function fails.
void vk_check(VkResult result, const char* what);

}  // namespace geodesic
