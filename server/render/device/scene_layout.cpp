#include "render/device/scene_layout.h"

#include "render/prepare/frame_uniforms.h"
#include "render/prepare/scene_bindings.h"
#include "render/device/vulkan_context.h"

namespace geodesic {

VkDescriptorType SceneLayout::descriptor_type(uint32_t binding) {
  if (binding == kSceneBinding) return VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  if (binding == kFrameBinding) return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

SceneLayout::SceneLayout(VkDevice device, const std::vector<uint32_t>& bindings)
    : device_(device) {
  std::vector<VkDescriptorSetLayoutBinding> entries;
  for (uint32_t b : bindings)
    entries.push_back({b, descriptor_type(b), 1, kShaderStages, nullptr});
  VkDescriptorSetLayoutCreateInfo layout{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  layout.bindingCount = static_cast<uint32_t>(entries.size());
  layout.pBindings = entries.data();
  vk_check(vkCreateDescriptorSetLayout(device, &layout, nullptr, &set_),
           "vkCreateDescriptorSetLayout");

  VkPushConstantRange push{kShaderStages, 0, sizeof(SampleRange)};
  VkPipelineLayoutCreateInfo pipeline{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pipeline.setLayoutCount = 1;
  pipeline.pSetLayouts = &set_;
  pipeline.pushConstantRangeCount = 1;
  pipeline.pPushConstantRanges = &push;
  vk_check(vkCreatePipelineLayout(device, &pipeline, nullptr, &pipeline_),
           "vkCreatePipelineLayout");
}

SceneLayout::~SceneLayout() {
  vkDestroyPipelineLayout(device_, pipeline_, nullptr);
  vkDestroyDescriptorSetLayout(device_, set_, nullptr);
}

}  // namespace geodesic
