#include "render/device/trace_backend.h"

namespace geodesic {

BackendKind resolve_backend(BackendKind wanted, const DeviceDescription& device) {
  if (wanted == BackendKind::RayQuery && !device.ray_query)
    throw VulkanError(device.name + ": VK_KHR_ray_query is not supported");
  if (wanted == BackendKind::RayTracingPipeline && !device.ray_tracing_pipeline)
    throw VulkanError(device.name + ": VK_KHR_ray_tracing_pipeline is not supported");
  if (wanted != BackendKind::Auto) return wanted;
  if (device.cpu && device.ray_query) return BackendKind::RayQuery;
  return device.ray_tracing_pipeline ? BackendKind::RayTracingPipeline : BackendKind::RayQuery;
}

std::unique_ptr<TraceBackend> make_backend(BackendKind kind, VulkanContext& ctx,
                                           SceneResources& res) {
  if (resolve_backend(kind, ctx.description()) == BackendKind::RayQuery)
    return make_ray_query_backend(ctx, res);
  return make_ray_tracing_backend(ctx, res);
}

BackendKind parse_backend(const std::string& name) {
  if (name == "auto") return BackendKind::Auto;
  if (name == "ray-query") return BackendKind::RayQuery;
  if (name == "pipeline") return BackendKind::RayTracingPipeline;
  throw std::invalid_argument("--backend: must be auto, ray-query or pipeline, not \"" + name +
                              "\"");
}

}  // namespace geodesic
