#include "render/device/storage_kernel.h"

#include <stdexcept>
#include <vector>

#include "render/device/shader_module.h"

namespace geodesic {

StorageKernel::StorageKernel(VulkanContext& ctx, std::span<const uint32_t> spirv, uint32_t buffers,
                             uint32_t push_bytes)
    : ctx_(ctx), buffers_(buffers), push_bytes_(push_bytes) {
  try {
    create(spirv);
  } catch (...) {
    release();  // what was made before the failing call; the destructor does not run
    throw;
  }
}

void StorageKernel::create(std::span<const uint32_t> spirv) {
  std::vector<VkDescriptorSetLayoutBinding> bindings(buffers_);
  for (uint32_t i = 0; i < buffers_; ++i)
    bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = buffers_;
  set_info.pBindings = bindings.data();
  vk_check(vkCreateDescriptorSetLayout(ctx_.device(), &set_info, nullptr, &set_layout_),
           "vkCreateDescriptorSetLayout");

  const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes_};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout_;
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  vk_check(vkCreatePipelineLayout(ctx_.device(), &layout_info, nullptr, &layout_),
           "vkCreatePipelineLayout");

  ShaderModule module(ctx_.device(), spirv);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module.handle();
  info.stage.pName = "main";
  info.layout = layout_;
  vk_check(vkCreateComputePipelines(ctx_.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
           "vkCreateComputePipelines");

  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers_};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  vk_check(vkCreateDescriptorPool(ctx_.device(), &pool_info, nullptr, &pool_),
           "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &set_layout_;
  vk_check(vkAllocateDescriptorSets(ctx_.device(), &alloc, &set_), "vkAllocateDescriptorSets");
}

StorageKernel::~StorageKernel() { release(); }

// Destroying a null handle does nothing, so this frees whatever create() got to.
void StorageKernel::release() {
  vkDestroyDescriptorPool(ctx_.device(), pool_, nullptr);
  vkDestroyPipeline(ctx_.device(), pipeline_, nullptr);
  vkDestroyPipelineLayout(ctx_.device(), layout_, nullptr);
  vkDestroyDescriptorSetLayout(ctx_.device(), set_layout_, nullptr);
}

void StorageKernel::bind(std::initializer_list<const GpuBuffer*> buffers) {
  if (buffers.size() != buffers_) throw std::invalid_argument("StorageKernel::bind: buffer count");
  std::vector<VkDescriptorBufferInfo> infos;
  std::vector<VkWriteDescriptorSet> writes;
  infos.reserve(buffers_);
  for (const GpuBuffer* buffer : buffers) {
    infos.push_back({buffer->handle(), 0, VK_WHOLE_SIZE});
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set_;
    write.dstBinding = static_cast<uint32_t>(writes.size());
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &infos.back();
    writes.push_back(write);
  }
  vkUpdateDescriptorSets(ctx_.device(), buffers_, writes.data(), 0, nullptr);
}

void StorageKernel::record(VkCommandBuffer cmd, const void* push, uint32_t groups) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes_, push);
  vkCmdDispatch(cmd, groups, 1, 1);
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace geodesic
