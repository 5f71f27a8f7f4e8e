// Loads compiled SPIR-V (built from shaders/ by glslang) into shader modules.
#pragma once

#include <filesystem>
#include <string>

#include "geometry/model.h"
#include "render/vulkan_context.h"

namespace geodesic {

// The SPIR-V folder: $GEODESIC_SHADER_DIR if set, else the build tree's.
std::filesystem::path shader_directory();

// Owns a VkShaderModule loaded from shader_directory()/<entry>.<geometry>.spv: each entry
// point is compiled once per model geometry.
class ShaderModule {
 public:
  ShaderModule(VkDevice device, const std::string& entry, GeometryKind geometry);
  ~ShaderModule();
  ShaderModule(const ShaderModule&) = delete;
  ShaderModule& operator=(const ShaderModule&) = delete;
  VkShaderModule handle() const { return module_; }

 private:
  VkDevice device_;
  VkShaderModule module_ = VK_NULL_HANDLE;
};

}  // namespace geodesic
