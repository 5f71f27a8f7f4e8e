#include "render/service/render_session.h"

#include <algorithm>
#include <cmath>


namespace geodesic {
namespace {

using Clock = RenderSession::Clock;

// After a move, frames are rendered at reduced resolution until the camera has been still this
// long (fast feedback while walking, full quality when still), as Cycles' viewport does: the
// divisor is chosen from the measured cost so that one sample of the frame takes about
// kMovingFrameSeconds.
constexpr double kSettleSeconds = 0.25;
constexpr double kMovingFrameSeconds = 0.03;
constexpr int kMaxMovingDivisor = 8;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

}  // namespace

void RenderSession::adopt(PreparedScene prepared) {
  renderer = std::move(prepared.renderer);
  non_finite = truncated = scene_non_finite = scene_truncated = 0;
  scene = std::move(prepared.scene);
  scene_name = std::move(prepared.name);
  scene_kind = prepared.kind;
  width = scene.render.width;
  height = scene.render.height;
  pose = scene.camera.pose;
  slicer.reset();
  reexpose = false;
  restart(false);
}

void RenderSession::rebase(std::unique_ptr<Renderer> rebuilt) {
  renderer = std::move(rebuilt);
  non_finite = truncated = 0;  // the new renderer's counters start from zero
  last_move = Clock::now();
  restart(true);
}

void RenderSession::restart(bool now_moving) {
  moving = now_moving;
  int divisor = 1;
  if (moving) {
    const double full_sample = slicer.seconds_per_pixel_sample() * width * height;
    divisor = std::clamp(int(std::ceil(std::sqrt(full_sample / kMovingFrameSeconds))), 2,
                         kMaxMovingDivisor);
  }
  const int w = std::max(16, width / divisor);
  const int h = std::max(16, height / divisor);
  // Moving frames also trace at most one bounce, with one light sample per vertex: direct
  // light shows the shapes, and the indirect light and the finer light sampling come back once
  // the camera is still.
  renderer->set_sampling(moving ? std::min(1, scene.render.max_depth) : scene.render.max_depth,
                         moving ? 1 : scene.render.light_samples);
  pose = renderer->set_view(pose, w, h);
  truncated = 0;  // set_view clears the tracer's counters, all but the non-finite one
  reset_time = Clock::now();
  slicer.restart();
  pass_shown = false;  // a new exposure waits for this view's first pass
  first_frame_due = true;
}

void RenderSession::serve(FrameEncoder& frames, ServiceStats& stats, double& pixel_samples) {
  if (reexpose) {
    reexpose = false;
    if (pass_shown) return frames.reexpose(stream, scene.render.exposure);
  }
  if (moving && seconds_since(last_move) > kSettleSeconds) restart(false);
  const bool pass_done = slicer.render_slice(*renderer);
  pixel_samples += slicer.last_pixel_samples();
  if (!pass_done) return;

  // A counter below the last one added belongs to a new renderer (after a device loss).
  const uint64_t now_non_finite = renderer->non_finite_samples();
  const uint64_t now_truncated = renderer->trace_counters().truncated_rays;
  const uint64_t new_non_finite =
      now_non_finite >= non_finite ? now_non_finite - non_finite : now_non_finite;
  const uint64_t new_truncated = now_truncated >= truncated ? now_truncated - truncated : now_truncated;
  non_finite = now_non_finite;
  truncated = now_truncated;
  scene_non_finite += new_non_finite;
  scene_truncated += new_truncated;
  stats.non_finite_samples += new_non_finite;
  stats.truncated_geodesics += new_truncated;
  first_frame_due = false;
  pass_shown = true;
  // The render thread goes on into this accumulation: the stream gets a copy. The error, the
  // frame number and the exposure's stops are filled in where it is resolved.
  const std::span<const float> sums = renderer->accumulation();
  frames.submit(stream, {{sums.begin(), sums.end()},
                         {0, renderer->samples(), seconds_since(reset_time), -1, renderer->width(),
                          renderer->height(), moving, 0, pose, scene_non_finite, scene_truncated},
                         scene.render.exposure});
}

void RenderSession::set_exposure(const Exposure& exposure) {
  scene.render.exposure = exposure;
  reexpose = true;
}

SceneInfo RenderSession::info() const {
  return {scene_name, geometry_name(scene.geometry), scene.manifold.name, width, height,
          scene.render.max_depth, scene.render.exposure, source_kind_name(scene_kind),
          scene.name.empty() ? scene_name : scene.name};
}

}  // namespace geodesic
