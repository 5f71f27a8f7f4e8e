// Back end 2: a VK_KHR_ray_tracing_pipeline pipeline. Ray generation runs the integrator; the
// shader binding table holds one miss record and one hit group per primitive kind (triangles;
// spheres with their intersection shader).
#include <cstring>
#include <vector>

#include "render/gpu_buffer.h"
#include "render/shader_module.h"
#include "render/trace_backend.h"

namespace geodesic {
namespace {

VkDeviceSize align_up(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

class RayTracingBackend : public TraceBackend {
 public:
  RayTracingBackend(VulkanContext& ctx, SceneResources& res) : ctx_(ctx), res_(res) {
    create_pipeline();
    create_binding_table();
  }

  ~RayTracingBackend() override { vkDestroyPipeline(ctx_.device(), pipeline_, nullptr); }

  const char* name() const override { return "pipeline"; }

  void record(VkCommandBuffer cmd, SampleRange range) override {
    VkDescriptorSet set = res_.descriptor_set();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, res_.pipeline_layout(),
                            0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, res_.pipeline_layout(), SceneResources::kShaderStages, 0,
                       sizeof(range), &range);
    VkStridedDeviceAddressRegionKHR callable{};
    ctx_.rt().cmd_trace_rays(cmd, &raygen_region_, &miss_region_, &hit_region_, &callable,
                             res_.width(), range.row_count, 1);
  }

 private:
  // Shader groups, in shader-binding-table order.
  enum Group : uint32_t { kRaygen, kMiss, kTriangleHit, kSphereHit, kGroupCount };

  void create_pipeline() {
    VkDevice device = ctx_.device();
    const GeometryKind g = res_.geometry();
    ShaderModule raygen(device, "raygen.rgen", g), miss(device, "miss.rmiss", g),
        triangle(device, "triangle.rchit", g), sphere_hit(device, "sphere.rchit", g),
        sphere_int(device, "sphere.rint", g);
    const std::pair<VkShaderStageFlagBits, VkShaderModule> modules[] = {
        {VK_SHADER_STAGE_RAYGEN_BIT_KHR, raygen.handle()},
        {VK_SHADER_STAGE_MISS_BIT_KHR, miss.handle()},
        {VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, triangle.handle()},
        {VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, sphere_hit.handle()},
        {VK_SHADER_STAGE_INTERSECTION_BIT_KHR, sphere_int.handle()}};
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    for (const auto& [stage, module] : modules) {
      VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
      info.stage = stage;
      info.module = module;
      info.pName = "main";
      stages.push_back(info);
    }

    auto group = [](VkRayTracingShaderGroupTypeKHR type, uint32_t general, uint32_t closest,
                    uint32_t intersection) {
      VkRayTracingShaderGroupCreateInfoKHR g{
          VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
      g.type = type;
      g.generalShader = general;
      g.closestHitShader = closest;
      g.anyHitShader = VK_SHADER_UNUSED_KHR;
      g.intersectionShader = intersection;
      return g;
    };
    constexpr uint32_t none = VK_SHADER_UNUSED_KHR;
    const VkRayTracingShaderGroupCreateInfoKHR groups[kGroupCount] = {
        group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, 0, none, none),
        group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, 1, none, none),
        group(VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR, none, 2, none),
        group(VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR, none, 3, 4)};

    VkRayTracingPipelineCreateInfoKHR info{VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
    info.stageCount = static_cast<uint32_t>(stages.size());
    info.pStages = stages.data();
    info.groupCount = kGroupCount;
    info.pGroups = groups;
    info.maxPipelineRayRecursionDepth = 1;  // only ray generation traces
    info.layout = res_.pipeline_layout();
    vk_check(ctx_.rt().create_ray_tracing_pipelines(device, VK_NULL_HANDLE, VK_NULL_HANDLE, 1,
                                                    &info, nullptr, &pipeline_),
             "vkCreateRayTracingPipelinesKHR");
  }

  void create_binding_table() {
    const auto& props = ctx_.pipeline_properties();
    const VkDeviceSize handle_size = props.shaderGroupHandleSize;
    const VkDeviceSize stride = align_up(handle_size, props.shaderGroupHandleAlignment);
    const VkDeviceSize base = props.shaderGroupBaseAlignment;

    std::vector<uint8_t> handles(handle_size * kGroupCount);
    vk_check(ctx_.rt().get_shader_group_handles(ctx_.device(), pipeline_, 0, kGroupCount,
                                                handles.size(), handles.data()),
             "vkGetRayTracingShaderGroupHandlesKHR");

    // Regions: raygen | miss | triangle hit, sphere hit; each base-aligned.
    const VkDeviceSize raygen_size = align_up(stride, base);
    const VkDeviceSize miss_size = align_up(stride, base);
    const VkDeviceSize hit_size = align_up(2 * stride, base);
    table_ = GpuBuffer(ctx_, raygen_size + miss_size + hit_size + base,
                       VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR);
    const VkDeviceAddress start = align_up(table_.address(), base);
    auto* bytes = static_cast<uint8_t*>(table_.mapped()) + (start - table_.address());
    auto copy = [&](Group g, VkDeviceSize offset) {
      std::memcpy(bytes + offset, handles.data() + g * handle_size, handle_size);
    };
    copy(kRaygen, 0);
    copy(kMiss, raygen_size);
    copy(kTriangleHit, raygen_size + miss_size);
    copy(kSphereHit, raygen_size + miss_size + stride);

    raygen_region_ = {start, raygen_size, raygen_size};
    miss_region_ = {start + raygen_size, stride, stride};
    hit_region_ = {start + raygen_size + miss_size, stride, 2 * stride};
  }

  VulkanContext& ctx_;
  SceneResources& res_;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  GpuBuffer table_;
  VkStridedDeviceAddressRegionKHR raygen_region_{}, miss_region_{}, hit_region_{};
};

}  // namespace

std::unique_ptr<TraceBackend> make_ray_tracing_backend(VulkanContext& ctx, SceneResources& res) {
  return std::make_unique<RayTracingBackend>(ctx, res);
}

}  // namespace geodesic
