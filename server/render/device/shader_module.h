// A VkShaderModule made from SPIR-V words (render/prepare/shader_compiler.h compiles them), destroyed
// with its owner: pipelines keep what they need after creation.
#pragma once

#include <cstdint>
#include <span>

#include "render/device/vulkan_context.h"

namespace geodesic {

class ShaderModule {
 public:
  ShaderModule(VkDevice device, std::span<const uint32_t> spirv);
  ~ShaderModule();
  ShaderModule(const ShaderModule&) = delete;
  ShaderModule& operator=(const ShaderModule&) = delete;
  VkShaderModule handle() const { return module_; }

 private:
  VkDevice device_;
  VkShaderModule module_ = VK_NULL_HANDLE;
};

}  // namespace geodesic
