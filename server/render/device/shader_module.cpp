#include "render/device/shader_module.h"

namespace geodesic {

ShaderModule::ShaderModule(VkDevice device, std::span<const uint32_t> spirv) : device_(device) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size() * 4;
  info.pCode = spirv.data();
  vk_check(vkCreateShaderModule(device_, &info, nullptr, &module_), "vkCreateShaderModule");
}

ShaderModule::~ShaderModule() { vkDestroyShaderModule(device_, module_, nullptr); }

}  // namespace geodesic
