// The descriptor set layout and pipeline layout of a scene's shaders: one set holding the
// bindings the pipeline's features use (render/prepare/scene_bindings.h), and the SampleRange push
// constant. Layouts made from the same bindings are compatible, so a pipeline cached for one
// scene binds another scene's descriptor set.
#pragma once

#include <vector>

#include <vulkan/vulkan.h>

namespace geodesic {

class SceneLayout {
 public:
  // Every stage that reads the scene's descriptor set and push constants.
  static constexpr VkShaderStageFlags kShaderStages =
      VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_RAYGEN_BIT_KHR |
      VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_INTERSECTION_BIT_KHR |
      VK_SHADER_STAGE_MISS_BIT_KHR;

  SceneLayout(VkDevice device, const std::vector<uint32_t>& bindings);
  ~SceneLayout();
  SceneLayout(const SceneLayout&) = delete;
  SceneLayout& operator=(const SceneLayout&) = delete;

  VkDescriptorSetLayout set() const { return set_; }
  VkPipelineLayout pipeline() const { return pipeline_; }
  static VkDescriptorType descriptor_type(uint32_t binding);

 private:
  VkDevice device_;
  VkDescriptorSetLayout set_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_ = VK_NULL_HANDLE;
};

}  // namespace geodesic
