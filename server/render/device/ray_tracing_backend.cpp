// Back end 2: a VK_KHR_ray_tracing_pipeline pipeline. Ray generation runs the integrator; the
// shader binding table holds one miss record and one hit group per primitive kind (triangles;
// spheres and shapes with their intersection shaders: kHitGroups), made only for the kinds
// the scene has.
#include <cstring>
#include <iterator>
#include <vector>

#include "render/device/gpu_buffer.h"
#include "render/device/shader_module.h"
#include "render/device/trace_backend.h"

namespace geodesic {
namespace {

VkDeviceSize align_up(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

// The hit group of each primitive kind, in the order of their hit records (HIT_RECORD_*,
// common/gpu_types.h), which the instances select (render/device/acceleration.cpp).
struct HitGroup {
  VkRayTracingShaderGroupTypeKHR type;
  const char* closest;
  const char* any;  // only where cells share mask bits
  const char* intersection;
  bool (*present)(const PipelineFeatures&);  // the kind is in the acceleration structure
};
constexpr HitGroup kHitGroups[] = {
    {VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR, "entry/triangle.rchit",
     "entry/triangle.rahit", nullptr, [](const PipelineFeatures& f) { return f.triangles; }},
    {VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR, "entry/sphere.rchit",
     "entry/sphere.rahit", "entry/sphere.rint",
     [](const PipelineFeatures& f) { return f.traced_spheres(); }},
    {VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR, "entry/shape.rchit",
     "entry/shape.rahit", "entry/shape.rint",
     [](const PipelineFeatures& f) { return f.traced_shapes(); }}};
constexpr uint32_t kHitRecords = std::size(kHitGroups);
static_assert(HIT_RECORD_TRIANGLES == 0 && HIT_RECORD_SPHERES == 1 && HIT_RECORD_SHAPES == 2);

class RayTracingBackend : public TraceBackend {
 public:
  RayTracingBackend(VulkanContext& ctx, SceneResources& res) : ctx_(ctx), res_(res) {
    const PipelineFeatures& f = res.features();
    pipeline_ = ctx.pipeline_cache().pipeline(
        name(), f, entries(),
        [&](const std::vector<Spirv>& spirv, const SceneLayout& layout, VkPipelineCache cache) {
          return create_pipeline(spirv, layout, cache);
        });
    create_binding_table();
  }

  const char* name() const override { return "pipeline"; }
  const CachedPipeline& pipeline() const override { return *pipeline_; }

  // Ray generation and miss, then the hit shaders of the primitive kinds present (with an
  // any-hit shader each where cells share mask bits).
  std::vector<std::string> entries() const override {
    const PipelineFeatures& f = res_.features();
    std::vector<std::string> e{"entry/raygen.rgen", "entry/miss.rmiss"};
    for (const HitGroup& g : kHitGroups) {
      if (!g.present(f)) continue;
      e.push_back(g.closest);
      if (g.intersection) e.push_back(g.intersection);
      if (f.shared_cell_masks) e.push_back(g.any);
    }
    return e;
  }

  void record(VkCommandBuffer cmd, SampleRange range) override {
    VkDescriptorSet set = res_.descriptor_set();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline_->pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, res_.pipeline_layout(),
                            0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, res_.pipeline_layout(), SceneLayout::kShaderStages, 0,
                       sizeof(range), &range);
    VkStridedDeviceAddressRegionKHR callable{};
    ctx_.rt().cmd_trace_rays(cmd, &raygen_region_, &miss_region_, &hit_region_, &callable,
                             range.column_count, range.row_count, 1);
  }

 private:
  // Groups in pipeline order: raygen, miss, then the hit groups of the kinds present.
  std::vector<const HitGroup*> hit_groups() const {
    std::vector<const HitGroup*> present;
    for (const HitGroup& g : kHitGroups)
      if (g.present(res_.features())) present.push_back(&g);
    return present;
  }
  uint32_t group_count() const { return 2u + uint32_t(hit_groups().size()); }

  VkPipeline create_pipeline(const std::vector<Spirv>& spirv, const SceneLayout& layout,
                             VkPipelineCache cache) const {
    VkDevice device = ctx_.device();
    const PipelineFeatures& f = res_.features();
    std::vector<std::unique_ptr<ShaderModule>> modules;
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    const std::vector<std::string> names = entries();
    for (size_t i = 0; i < spirv.size(); ++i) {
      static const std::pair<const char*, VkShaderStageFlagBits> kStages[] = {
          {".rgen", VK_SHADER_STAGE_RAYGEN_BIT_KHR},
          {".rmiss", VK_SHADER_STAGE_MISS_BIT_KHR},
          {".rchit", VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR},
          {".rahit", VK_SHADER_STAGE_ANY_HIT_BIT_KHR},
          {".rint", VK_SHADER_STAGE_INTERSECTION_BIT_KHR}};
      modules.push_back(std::make_unique<ShaderModule>(device, *spirv[i]));
      VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
      for (const auto& [ext, stage] : kStages)
        if (names[i].ends_with(ext)) info.stage = stage;
      info.module = modules.back()->handle();
      info.pName = "main";
      stages.push_back(info);
    }

    constexpr uint32_t none = VK_SHADER_UNUSED_KHR;
    // The stage index of an entry (`names` is in stage order), or none.
    auto stage_of = [&](const char* entry) {
      for (uint32_t i = 0; i < names.size(); ++i)
        if (names[i] == entry) return i;
      return none;
    };
    auto group = [&](VkRayTracingShaderGroupTypeKHR type, uint32_t general, const char* closest,
                     const char* any, const char* intersection) {
      VkRayTracingShaderGroupCreateInfoKHR g{
          VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
      g.type = type;
      g.generalShader = general;
      g.closestHitShader = closest ? stage_of(closest) : none;
      g.anyHitShader = any ? stage_of(any) : none;
      g.intersectionShader = intersection ? stage_of(intersection) : none;
      return g;
    };
    std::vector<VkRayTracingShaderGroupCreateInfoKHR> groups = {
        group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, 0, nullptr, nullptr, nullptr),
        group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, 1, nullptr, nullptr, nullptr)};
    for (const HitGroup* g : hit_groups())
      groups.push_back(group(g->type, none, g->closest, g->any, g->intersection));

    VkRayTracingPipelineCreateInfoKHR info{VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
    if (f.primitive_culling && !f.traced_boxes())
      info.flags |= VK_PIPELINE_CREATE_RAY_TRACING_SKIP_AABBS_BIT_KHR;
    if (f.primitive_culling && !f.triangles)
      info.flags |= VK_PIPELINE_CREATE_RAY_TRACING_SKIP_TRIANGLES_BIT_KHR;
    info.stageCount = static_cast<uint32_t>(stages.size());
    info.pStages = stages.data();
    info.groupCount = static_cast<uint32_t>(groups.size());
    info.pGroups = groups.data();
    info.maxPipelineRayRecursionDepth = 1;  // only ray generation traces
    info.layout = layout.pipeline();
    VkPipeline pipeline = VK_NULL_HANDLE;
    vk_check(ctx_.rt().create_ray_tracing_pipelines(device, VK_NULL_HANDLE, cache, 1, &info,
                                                    nullptr, &pipeline),
             "vkCreateRayTracingPipelinesKHR");
    return pipeline;
  }

  void create_binding_table() {
    const auto& props = ctx_.pipeline_properties();
    const VkDeviceSize handle_size = props.shaderGroupHandleSize;
    const VkDeviceSize stride = align_up(handle_size, props.shaderGroupHandleAlignment);
    const VkDeviceSize base = props.shaderGroupBaseAlignment;

    const uint32_t groups = group_count();
    std::vector<uint8_t> handles(handle_size * groups);
    vk_check(ctx_.rt().get_shader_group_handles(ctx_.device(), pipeline_->pipeline, 0, groups,
                                                handles.size(), handles.data()),
             "vkGetRayTracingShaderGroupHandlesKHR");

    // Regions: raygen | miss | one hit record per kind (kHitGroups); each base-aligned.
    // Instances pick their hit record by kind (HIT_RECORD_*, common/gpu_types.h); a kind the
    // scene lacks is never hit, and its record repeats the first present one.
    const VkDeviceSize raygen_size = align_up(stride, base);
    const VkDeviceSize miss_size = align_up(stride, base);
    const VkDeviceSize hit_size = align_up(kHitRecords * stride, base);
    table_ = GpuBuffer(ctx_, raygen_size + miss_size + hit_size + base,
                       VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR);
    const VkDeviceAddress start = align_up(table_.address(), base);
    auto* bytes = static_cast<uint8_t*>(table_.mapped()) + (start - table_.address());
    auto copy = [&](uint32_t group, VkDeviceSize offset) {
      std::memcpy(bytes + offset, handles.data() + group * handle_size, handle_size);
    };
    copy(0, 0);
    copy(1, raygen_size);
    const std::vector<const HitGroup*> present = hit_groups();
    for (uint32_t record = 0; record < kHitRecords && !present.empty(); ++record) {
      uint32_t group = 2;  // the first present kind's, unless this record's kind is present
      for (uint32_t i = 0; i < present.size(); ++i)
        if (present[i] == &kHitGroups[record]) group = 2 + i;
      copy(group, raygen_size + miss_size + record * stride);
    }

    raygen_region_ = {start, raygen_size, raygen_size};
    miss_region_ = {start + raygen_size, stride, stride};
    hit_region_ = {start + raygen_size + miss_size, stride, kHitRecords * stride};
  }

  VulkanContext& ctx_;
  SceneResources& res_;
  std::shared_ptr<const CachedPipeline> pipeline_;
  GpuBuffer table_;
  VkStridedDeviceAddressRegionKHR raygen_region_{}, miss_region_{}, hit_region_{};
};

}  // namespace

std::unique_ptr<TraceBackend> make_ray_tracing_backend(VulkanContext& ctx, SceneResources& res) {
  return std::make_unique<RayTracingBackend>(ctx, res);
}

}  // namespace geodesic
