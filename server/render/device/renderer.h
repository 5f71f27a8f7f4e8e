// Progressive rendering of one scene on one device: each call adds samples to the float
// accumulation buffers (sum and count per pixel, even and odd samples apart); image() is the
// running mean and estimated_error() compares the two halves.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "geometry/wide_isometry.h"
#include "render/prepare/cells.h"
#include "render/prepare/image.h"
#include "render/device/scene_resources.h"
#include "render/device/trace_backend.h"

namespace geodesic {

// A rectangle of pixels.
struct PixelRegion {
  uint32_t column = 0, row = 0, columns = 0, rows = 0;
};

class Renderer {
 public:
  // `variant`: the scene's specialised pipeline, or the all-features one (the baseline the
  // benchmarks and the equivalence tests compare it with).
  Renderer(VulkanContext& ctx, const Scene& scene, BackendKind backend = BackendKind::Auto,
           PipelineVariant variant = PipelineVariant::Specialised);

  // Adds `samples` samples per pixel, in one submission.
  void add_samples(uint32_t samples);
  // A slice of a pass: adds `samples` samples (numbered from samples()) to the pixels of
  // `region` only; finish_pass(samples) counts them once every pixel has had them
  // (render/service/pass_slicer.h cuts passes so).
  void render_region(uint32_t samples, const PixelRegion& region);
  void finish_pass(uint32_t samples) { samples_ += samples; }
  uint32_t samples() const { return samples_; }
  uint64_t traced_rays() const { return resources_.traced_rays(); }
  uint32_t non_finite_samples() const { return resources_.non_finite_samples(); }
  TraceCounters trace_counters() const { return resources_.trace_counters(); }
  // Starts over (e.g. after the camera moved); sample indices restart too.
  void reset();

  // A new camera isometry (carried into the fundamental domain) and a resolution no larger
  // than the scene's; starts over. Returns the pose as placed.
  Mat4 set_view(const Mat4& camera_pose, int width, int height);
  // In a space without a quotient (E3, H3: one chart without faces) the renderer works in a
  // frame centred on the camera it was built for: the scene is moved by the frame's inverse
  // (in binary128 in H3: scene/scene_isometry.h) before anything is stored in float, so an
  // image does not depend on where the whole scene sits (docs/numerics.md). Poses in and out are the scene's. True when `camera_pose`
  // has strayed so far from the frame's centre that a renderer built there should replace
  // this one (a walking camera: render/service/render_service.h).
  bool frame_outgrown(const Mat4& camera_pose) const;
  // The bounces and the light samples per vertex (clamped to 1 .. kMaxLightSamples); starts
  // over.
  void set_sampling(int max_depth, int light_samples);
  int width() const { return int(resources_.width()); }
  int height() const { return int(resources_.height()); }

  // The accumulation of the current view (2 halves x width x height x rgba sums), and the
  // sample count it holds: a checkpoint, valid between passes (after finish_pass).
  std::span<const float> accumulation() const;
  // Puts a checkpoint of the same view back. Sample indices go on from `samples`, so the
  // samples added afterwards have their own random streams (independent of those already in
  // the sums): the result stays an unbiased estimate. Throws std::invalid_argument on a size
  // mismatch.
  void restore(uint32_t samples, std::span<const float> sums);

  Image image() const;
  // Relative RMS error of image(), from the difference of the even and odd halves
  // (estimated_relative_rmse, docs/numerics.md); negative until both halves have a sample.
  double estimated_error() const;

  const char* backend_name() const { return backend_->name(); }
  const TraceBackend& backend() const { return *backend_; }
  const PipelineFeatures& features() const { return resources_.features(); }
  const VulkanContext& context() const { return ctx_; }

 private:
  VulkanContext& ctx_;
  GeometryKind geometry_;
  std::vector<Cell> cells_;
  bool camera_relative_;
  // From the scene's coordinates to those of the frame the device works in (the identity in a
  // quotient).
  WideIsometry into_frame_;
  SceneResources resources_;
  std::unique_ptr<TraceBackend> backend_;
  uint32_t samples_ = 0;
};

}  // namespace geodesic
