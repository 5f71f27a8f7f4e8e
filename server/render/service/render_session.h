// One interactive session of the render service (render/service/render_service.h): its scene and
// renderer, camera, view and pass slicer, and the stream its frames go out on after each pass
// (encoded there, off the render thread: render/service/frame_encoder.h). Not thread-safe: the
// service's lock guards it; only the render thread renders it.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "render/service/frame_encoder.h"
#include "render/service/pass_slicer.h"
#include "render/service/render_service.h"

namespace geodesic {

struct RenderSession {
  using Clock = std::chrono::steady_clock;

  std::shared_ptr<FrameEncoder::Stream> stream;
  RenderService::FailureCallback on_failure;
  Scene scene;
  std::string scene_name;
  SceneSource::Kind scene_kind = SceneSource::Kind::Bundled;
  std::unique_ptr<Renderer> renderer;
  Mat4 pose;
  int width = 0, height = 0;  // the full resolution asked for
  bool moving = false;
  Clock::time_point last_move, reset_time;
  PassSlicer slicer{RenderService::kSliceSeconds};
  // The renderer's device counters as last added to the totals (the truncated count starts over
  // with each view), and the totals since the scene was installed, which frames report.
  uint64_t non_finite = 0, truncated = 0;
  uint64_t scene_non_finite = 0, scene_truncated = 0;
  // A pass of this view has gone to the stream: a new exposure re-encodes its image.
  bool pass_shown = false;
  bool reexpose = false;
  // A new view (opened, moved, resized, another scene) whose first frame has not gone out yet.
  bool first_frame_due = true;

  // A new scene, its renderer built: the camera goes to the scene's pose, at full resolution.
  void adopt(PreparedScene prepared);
  // A renderer of the same scene built at the camera (Renderer::frame_outgrown): the view,
  // settings and counters go on; the accumulation starts over as after a move.
  void rebase(std::unique_ptr<Renderer> rebuilt);
  // A new view: reduced resolution while moving, full when still; accumulation starts over.
  void restart(bool moving);
  // One slice of the current pass (after a move, full resolution once the camera has settled);
  // when the slice completed the pass, a copy of its accumulation goes to `frames` to be
  // resolved and encoded. Adds the slice's pixel samples to `pixel_samples` and the pass's
  // counters to `stats`.
  void serve(FrameEncoder& frames, ServiceStats& stats, double& pixel_samples);
  SceneInfo info() const;
  // Sets the exposure; the last pass is encoded again with it at the next serve().
  void set_exposure(const Exposure& exposure);
  // Someone waits for this session's next frame: a new view's first, or a new exposure's.
  bool urgent() const { return first_frame_due || reexpose; }
};

}  // namespace geodesic
