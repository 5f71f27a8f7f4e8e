// The thin, device-specific part of rendering: how one batch of samples gets traced. The
// integrator itself is shared GLSL; each back end is one entry point around it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "render/device/pipeline_cache.h"
#include "render/device/scene_resources.h"

namespace geodesic {

enum class BackendKind { Auto, RayQuery, RayTracingPipeline };

class TraceBackend {
 public:
  virtual ~TraceBackend() = default;
  virtual const char* name() const = 0;
  // Its pipeline (shared through the device's PipelineCache) and the shaders/ entry points it
  // is made of.
  virtual const CachedPipeline& pipeline() const = 0;
  virtual std::vector<std::string> entries() const = 0;
  // Records a dispatch adding `range` samples to every pixel of its rectangle.
  virtual void record(VkCommandBuffer cmd, SampleRange range) = 0;
};

std::unique_ptr<TraceBackend> make_ray_query_backend(VulkanContext& ctx, SceneResources& res);
std::unique_ptr<TraceBackend> make_ray_tracing_backend(VulkanContext& ctx, SceneResources& res);

// Auto picks by device, from measurements (docs/benchmarks.md): ray queries on lavapipe
// (~1.25x faster there), the ray-tracing pipeline on GPUs (whose drivers support it best).
BackendKind resolve_backend(BackendKind wanted, const DeviceDescription& device);
std::unique_ptr<TraceBackend> make_backend(BackendKind kind, VulkanContext& ctx,
                                           SceneResources& res);

BackendKind parse_backend(const std::string& name);  // "auto" | "ray-query" | "pipeline"

}  // namespace geodesic
