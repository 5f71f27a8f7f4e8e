// Progressive rendering of one scene on one device: each call adds samples to the float
// accumulation buffer (sum and count per pixel); image() is the running mean.
#pragma once

#include <memory>

#include "render/image.h"
#include "render/scene_resources.h"
#include "render/trace_backend.h"

namespace geodesic {

class Renderer {
 public:
  Renderer(VulkanContext& ctx, const Scene& scene, BackendKind backend = BackendKind::Auto);

  // Adds `samples` samples per pixel, in one submission.
  void add_samples(uint32_t samples);
  uint32_t samples() const { return samples_; }
  uint64_t traced_rays() const { return resources_.traced_rays(); }
  uint32_t non_finite_samples() const { return resources_.non_finite_samples(); }
  // Starts over (e.g. after the camera moved); sample indices restart too.
  void reset();

  Image image() const;
  const char* backend_name() const { return backend_->name(); }
  const VulkanContext& context() const { return ctx_; }

 private:
  VulkanContext& ctx_;
  SceneResources resources_;
  std::unique_ptr<TraceBackend> backend_;
  uint32_t samples_ = 0;
};

}  // namespace geodesic
