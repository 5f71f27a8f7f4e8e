// Everything a scene needs on the device: its buffers, acceleration structures, the
// accumulation buffer, and the one descriptor set both tracing back ends bind. Only the
// buffers its pipeline's features read are made and bound.
#pragma once

#include <memory>

#include "render/device/acceleration.h"
#include "render/prepare/frame_uniforms.h"
#include "render/device/gpu_buffer.h"
#include "render/prepare/packed_scene.h"
#include "render/prepare/pipeline_features.h"
#include "render/device/scene_layout.h"
#include "scene/scene.h"

namespace geodesic {

// The Diagnostics buffer (binding 14, shaders/common/scene_data.glsl).
struct DeviceDiagnostics {
  uint32_t non_finite_samples;  // since the scene was loaded
  uint32_t crossed_faces;       // since the last clear, walls between pieces included
  uint32_t truncated_rays;      // rays given up at MAX_CROSSINGS, since the last clear
};

// What the tracer did since the last clear: chart segments traced (each a traversal), faces
// crossed, and rays cut off at the crossing bound.
struct TraceCounters {
  uint64_t traced_rays = 0;
  uint64_t crossed_faces = 0;
  uint64_t truncated_rays = 0;
};

class SceneResources {
 public:
  SceneResources(VulkanContext& ctx, const Scene& scene,
                 PipelineVariant variant = PipelineVariant::Specialised);
  ~SceneResources();
  SceneResources(const SceneResources&) = delete;
  SceneResources& operator=(const SceneResources&) = delete;

  VkDescriptorSet descriptor_set() const { return set_; }
  VkPipelineLayout pipeline_layout() const { return layout_->pipeline(); }
  // What the scene's pipeline must compile in (the device's primitive culling included).
  const PipelineFeatures& features() const { return features_; }
  const FrameUniforms& uniforms() const { return uniforms_; }
  GeometryKind geometry() const { return geometry_; }
  uint32_t width() const { return uniforms_.width; }
  uint32_t height() const { return uniforms_.height; }

  const PackedScene& packed() const { return packed_; }

  // Running per-pixel sums (rgb = radiance sum, a = sample count) of the current width x
  // height, in two halves: even-numbered samples, then odd-numbered ones.
  const float* accumulation() const { return static_cast<const float*>(accumulation_.mapped()); }
  void clear_accumulation();
  // Overwrites the accumulation of the current view with `sums` (its size: a checkpoint).
  void load_accumulation(const float* sums);
  // New camera and/or a resolution up to the allocated one (reduced while moving); clears.
  void set_view(const Mat4& camera_pose, uint32_t camera_cell, uint32_t width, uint32_t height);
  // The bounces and the light samples per vertex (render.max_depth, render.light_samples, the
  // latter clamped to 1 .. MAX_LIGHT_SAMPLES); clears.
  void set_sampling(uint32_t max_depth, int light_samples);
  // Rays traced since the last clear, summed over pixels.
  uint64_t traced_rays() const;
  // Samples the integrator dropped for being NaN or infinite, since the scene was loaded.
  uint32_t non_finite_samples() const;
  // The tracer's device counters since the last clear.
  TraceCounters trace_counters() const;

 private:
  void create_descriptors();

  VulkanContext& ctx_;
  GeometryKind geometry_;
  PackedScene packed_;
  PipelineFeatures features_;
  FrameUniforms uniforms_{};
  size_t capacity_ = 0;  // pixels the buffers hold
  SceneAccelerationStructures structures_;
  GpuBuffer frame_, accumulation_, spheres_, materials_, lights_, positions_, normals_,
      indices_, triangles_, ray_counts_, sphere_refs_, cells_, faces_, diagnostics_, emitters_,
      light_images_, tubes_, shapes_, shape_refs_, listed_;
  std::unique_ptr<SceneLayout> layout_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace geodesic
