#include "render/shader_module.h"

#include <cstdlib>
#include <fstream>
#include <vector>

namespace geodesic {

std::filesystem::path shader_directory() {
  if (const char* dir = std::getenv("GEODESIC_SHADER_DIR")) return dir;
  return GEODESIC_SHADER_DIR;
}

ShaderModule::ShaderModule(VkDevice device, const std::string& entry, GeometryKind geometry)
    : device_(device) {
  const auto path = shader_directory() / (entry + "." + geometry_name(geometry) + ".spv");
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) throw VulkanError("cannot read shader " + path.string());
  std::vector<uint32_t> code(static_cast<size_t>(file.tellg()) / 4);
  file.seekg(0);
  file.read(reinterpret_cast<char*>(code.data()), static_cast<std::streamsize>(code.size() * 4));
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = code.size() * 4;
  info.pCode = code.data();
  vk_check(vkCreateShaderModule(device_, &info, nullptr, &module_), "vkCreateShaderModule");
}

ShaderModule::~ShaderModule() { vkDestroyShaderModule(device_, module_, nullptr); }

}  // namespace geodesic
