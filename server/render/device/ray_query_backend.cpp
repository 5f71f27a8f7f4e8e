// Back end 1: the integrator as a compute shader tracing with ray queries.
#include "render/device/pipeline_cache.h"
#include "render/device/shader_module.h"
#include "render/device/trace_backend.h"

namespace geodesic {
namespace {

constexpr uint32_t kGroupSizeX = 8, kGroupSizeY = 8;  // ray_query.comp local_size

class RayQueryBackend : public TraceBackend {
 public:
  RayQueryBackend(VulkanContext& ctx, SceneResources& res) : res_(res) {
    pipeline_ = ctx.pipeline_cache().pipeline(
        name(), res.features(), entries(),
        [&](const std::vector<Spirv>& spirv, const SceneLayout& layout, VkPipelineCache cache) {
          ShaderModule module(ctx.device(), *spirv[0]);
          VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
          info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
          info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
          info.stage.module = module.handle();
          info.stage.pName = "main";
          info.layout = layout.pipeline();
          VkPipeline pipeline = VK_NULL_HANDLE;
          vk_check(vkCreateComputePipelines(ctx.device(), cache, 1, &info, nullptr, &pipeline),
                   "vkCreateComputePipelines");
          return pipeline;
        });
  }

  const char* name() const override { return "ray-query"; }
  const CachedPipeline& pipeline() const override { return *pipeline_; }
  std::vector<std::string> entries() const override { return {"entry/ray_query.comp"}; }

  void record(VkCommandBuffer cmd, SampleRange range) override {
    VkDescriptorSet set = res_.descriptor_set();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_->pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, res_.pipeline_layout(), 0, 1,
                            &set, 0, nullptr);
    vkCmdPushConstants(cmd, res_.pipeline_layout(), SceneLayout::kShaderStages, 0, sizeof(range),
                       &range);
    vkCmdDispatch(cmd, (range.column_count + kGroupSizeX - 1) / kGroupSizeX,
                  (range.row_count + kGroupSizeY - 1) / kGroupSizeY, 1);
  }

 private:
  SceneResources& res_;
  std::shared_ptr<const CachedPipeline> pipeline_;
};

}  // namespace

std::unique_ptr<TraceBackend> make_ray_query_backend(VulkanContext& ctx, SceneResources& res) {
  return std::make_unique<RayQueryBackend>(ctx, res);
}

}  // namespace geodesic
