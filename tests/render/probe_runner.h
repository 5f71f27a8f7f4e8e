// Runs a test probe: a compute shader reading an array of cases from binding 0 and writing one
// result per case to binding 1, with the case count as its only push constant. Probes are
// compiled at run time for one model geometry, like every entry point.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "render/device/gpu_buffer.h"
#include "render/prepare/pipeline_features.h"
#include "render/prepare/shader_compiler.h"
#include "render/device/shader_module.h"
#include "render/device/vulkan_context.h"

namespace geodesic::test {

class ProbeRunner {
 public:
  static constexpr uint32_t kGroupSize = 64;  // local_size_x of every probe shader

  ProbeRunner(VulkanContext& ctx, const std::string& shader, GeometryKind geometry) : ctx_(ctx) {
    VkDescriptorSetLayoutBinding bindings[2]{};
    for (uint32_t i = 0; i < 2; ++i) {
      bindings[i].binding = i;
      bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      bindings[i].descriptorCount = 1;
      bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = 2;
    set_info.pBindings = bindings;
    vk_check(vkCreateDescriptorSetLayout(ctx.device(), &set_info, nullptr, &set_layout_),
             "vkCreateDescriptorSetLayout");

    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(uint32_t)};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout_;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &push;
    vk_check(vkCreatePipelineLayout(ctx.device(), &layout_info, nullptr, &layout_),
             "vkCreatePipelineLayout");

    ShaderModule module(ctx.device(), compile_shader(shader, {geometry_define(geometry)}).spirv);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module.handle();
    info.stage.pName = "main";
    info.layout = layout_;
    vk_check(vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
             "vkCreateComputePipelines");

    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = 1;
    pool_info.pPoolSizes = &size;
    vk_check(vkCreateDescriptorPool(ctx.device(), &pool_info, nullptr, &pool_),
             "vkCreateDescriptorPool");
  }

  ~ProbeRunner() {
    vkDestroyDescriptorPool(ctx_.device(), pool_, nullptr);
    vkDestroyPipeline(ctx_.device(), pipeline_, nullptr);
    vkDestroyPipelineLayout(ctx_.device(), layout_, nullptr);
    vkDestroyDescriptorSetLayout(ctx_.device(), set_layout_, nullptr);
  }
  ProbeRunner(const ProbeRunner&) = delete;
  ProbeRunner& operator=(const ProbeRunner&) = delete;

  // One result per case. Case and Result must match the shader's std430 structs.
  template <typename Result, typename Case>
  std::vector<Result> run(const std::vector<Case>& cases) {
    const auto count = static_cast<uint32_t>(cases.size());
    GpuBuffer input = GpuBuffer::from_vector(ctx_, cases, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    GpuBuffer output(ctx_, std::max<VkDeviceSize>(1, count) * sizeof(Result),
                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

    vk_check(vkResetDescriptorPool(ctx_.device(), pool_, 0), "vkResetDescriptorPool");
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = pool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout_;
    VkDescriptorSet set = VK_NULL_HANDLE;
    vk_check(vkAllocateDescriptorSets(ctx_.device(), &alloc, &set), "vkAllocateDescriptorSets");
    const VkDescriptorBufferInfo buffers[2] = {{input.handle(), 0, VK_WHOLE_SIZE},
                                               {output.handle(), 0, VK_WHOLE_SIZE}};
    VkWriteDescriptorSet writes[2]{};
    for (uint32_t i = 0; i < 2; ++i) {
      writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      writes[i].dstSet = set;
      writes[i].dstBinding = i;
      writes[i].descriptorCount = 1;
      writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      writes[i].pBufferInfo = &buffers[i];
    }
    vkUpdateDescriptorSets(ctx_.device(), 2, writes, 0, nullptr);

    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 0, nullptr);
      vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(count), &count);
      vkCmdDispatch(cmd, (count + kGroupSize - 1) / kGroupSize, 1, 1);
      // Make the shader's writes visible to the host read below.
      VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
      barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                           0, 1, &barrier, 0, nullptr, 0, nullptr);
    });

    std::vector<Result> results(count);
    std::memcpy(results.data(), output.mapped(), count * sizeof(Result));
    return results;
  }

 private:
  VulkanContext& ctx_;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

}  // namespace geodesic::test
