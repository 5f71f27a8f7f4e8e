// What double precision costs on the device: the sphere-intersection arithmetic of
// bench/float64_cost.comp, compiled for float and for double, run over the same 10^6 cases
// (64 intersections each); prints the best of five timed runs and the ratio (docs/numerics.md).
//   float64_cost [--device NAME|INDEX] [--invocations N] [--repeats R]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/device/gpu_buffer.h"
#include "render/device/vulkan_context.h"

namespace {

using namespace geodesic;

std::vector<uint32_t> read_spirv(const std::string& path) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) throw std::runtime_error("cannot read " + path);
  std::vector<uint32_t> code(static_cast<size_t>(file.tellg()) / 4);
  file.seekg(0);
  file.read(reinterpret_cast<char*>(code.data()), code.size() * 4);
  return code;
}

struct Push {
  uint32_t count;
  uint32_t repeats;
};

// The kernel's one storage buffer (a float per invocation) and one pipeline per precision, on
// the renderer's device (which enables shaderFloat64 where the device has it).
class Bench {
 public:
  Bench(VulkanContext& ctx, uint32_t invocations)
      : ctx_(ctx),
        invocations_(invocations),
        output_(ctx, invocations * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {
    if (!ctx.description().float64)
      throw std::runtime_error(ctx.description().name + " has no shaderFloat64");
    create_layout();
  }

  ~Bench() {
    VkDevice device = ctx_.device();
    vkDeviceWaitIdle(device);
    for (VkPipeline p : pipelines_) vkDestroyPipeline(device, p, nullptr);
    vkDestroyDescriptorPool(device, descriptor_pool_, nullptr);
    vkDestroyPipelineLayout(device, pipeline_layout_, nullptr);
    vkDestroyDescriptorSetLayout(device, set_layout_, nullptr);
  }

  VkPipeline pipeline(const std::string& spirv_path) {
    const std::vector<uint32_t> code = read_spirv(spirv_path);
    VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    module_info.codeSize = code.size() * 4;
    module_info.pCode = code.data();
    VkShaderModule module;
    vk_check(vkCreateShaderModule(ctx_.device(), &module_info, nullptr, &module),
             "vkCreateShaderModule");
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.layout = pipeline_layout_;
    VkPipeline pipeline;
    vk_check(vkCreateComputePipelines(ctx_.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
             "vkCreateComputePipelines");
    vkDestroyShaderModule(ctx_.device(), module, nullptr);
    pipelines_.push_back(pipeline);
    return pipeline;
  }

  // Seconds for one dispatch over every invocation, and the sum of the outputs.
  std::pair<double, double> run(VkPipeline pipeline, uint32_t repeats) {
    const auto start = std::chrono::steady_clock::now();
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set_,
                              0, nullptr);
      const Push push{invocations_, repeats};
      vkCmdPushConstants(cmd, pipeline_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push),
                         &push);
      vkCmdDispatch(cmd, (invocations_ + 63) / 64, 1, 1);
    });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto* values = static_cast<const float*>(output_.mapped());
    double sum = 0;
    for (uint32_t i = 0; i < invocations_; ++i) sum += values[i];
    return {seconds, sum};
  }

 private:
  void create_layout() {
    VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                                         VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = 1;
    set_info.pBindings = &binding;
    vk_check(vkCreateDescriptorSetLayout(ctx_.device(), &set_info, nullptr, &set_layout_),
          "vkCreateDescriptorSetLayout");
    const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(Push)};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout_;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &range;
    vk_check(vkCreatePipelineLayout(ctx_.device(), &layout_info, nullptr, &pipeline_layout_),
          "vkCreatePipelineLayout");
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = 1;
    pool_info.pPoolSizes = &size;
    vk_check(vkCreateDescriptorPool(ctx_.device(), &pool_info, nullptr, &descriptor_pool_),
          "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = descriptor_pool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout_;
    vk_check(vkAllocateDescriptorSets(ctx_.device(), &alloc, &set_), "vkAllocateDescriptorSets");
    const VkDescriptorBufferInfo buffer{output_.handle(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set_;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &buffer;
    vkUpdateDescriptorSets(ctx_.device(), 1, &write, 0, nullptr);
  }

  VulkanContext& ctx_;
  uint32_t invocations_;
  GpuBuffer output_;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  std::vector<VkPipeline> pipelines_;
};

}  // namespace

int main(int argc, char** argv) {
  std::string device = "";
  uint32_t invocations = 1u << 20, repeats = 64;  // 10^6 cases, each intersected 64 times
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--device" && i + 1 < argc) device = argv[++i];
    else if (a == "--invocations" && i + 1 < argc) invocations = std::stoul(argv[++i]);
    else if (a == "--repeats" && i + 1 < argc) repeats = std::stoul(argv[++i]);
  }
  try {
    VulkanContext ctx(device);
    Bench bench(ctx, invocations);
    const double intersections = double(invocations) * repeats;
    std::printf("%s: %.3g sphere intersections per dispatch, best of 5\n", ctx.description().name.c_str(),
                intersections);
    double best[2] = {1e300, 1e300};
    const char* precisions[2] = {"float", "double"};
    for (int p = 0; p < 2; ++p) {
      const VkPipeline pipeline = bench.pipeline(std::string(FLOAT64_COST_SPV_DIR) +
                                                 "/float64_cost." + precisions[p] + ".spv");
      bench.run(pipeline, repeats);  // warm-up
      double sum = 0;
      for (int r = 0; r < 5; ++r) {
        const auto [seconds, s] = bench.run(pipeline, repeats);
        best[p] = std::min(best[p], seconds);
        sum = s;
      }
      std::printf("  %-6s %8.2f ms  %8.1f M intersections/s  (checksum %.9g)\n", precisions[p],
                  best[p] * 1e3, intersections / best[p] * 1e-6, sum);
    }
    std::printf("  double / float time: %.2fx\n", best[1] / best[0]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "float64_cost: %s\n", e.what());
    return 1;
  }
}
