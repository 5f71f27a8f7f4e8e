// One interactive session of the render service (render/render_service.h): its scene and
// renderer, camera, view and pass slicer, and the frame it streams after each pass. Not
// thread-safe: the service's lock guards it; only the render thread renders it.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "render/jpeg_encoder.h"
#include "render/pass_slicer.h"
#include "render/render_service.h"

namespace geodesic {

struct RenderSession {
  using Clock = std::chrono::steady_clock;

  RenderService::FrameCallback on_frame;
  RenderService::FailureCallback on_failure;
  Scene scene;
  std::string scene_name;
  SceneSource::Kind scene_kind = SceneSource::Kind::Bundled;
  std::unique_ptr<Renderer> renderer;
  Mat4 pose;
  int width = 0, height = 0;  // the full resolution asked for
  bool moving = false;
  Clock::time_point last_move, reset_time;
  uint64_t frame = 0;
  PassSlicer slicer{RenderService::kSliceSeconds};
  // The renderer's device counters as last added to the totals (the truncated count starts over
  // with each view), and the totals since the scene was installed, which frames report.
  uint64_t non_finite = 0, truncated = 0;
  uint64_t scene_non_finite = 0, scene_truncated = 0;
  // The last complete pass, linear, and its frame's description: a new exposure re-encodes it.
  Image last_image;
  FrameInfo last_info;
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
  // the frame, encoded, when the slice completed the pass, else null. Adds the slice's pixel
  // samples to `pixel_samples` and the frame's encode time and counters to `stats`.
  std::shared_ptr<EncodedFrame> serve(JpegEncoder& encoder, ServiceStats& stats,
                                      double& pixel_samples);
  SceneInfo info() const;
  // Sets the exposure; the last frame is encoded again with it at the next serve().
  void set_exposure(const Exposure& exposure);
  // Someone waits for this session's next frame: a new view's first, or a new exposure's.
  bool urgent() const { return first_frame_due || reexpose; }

 private:
  std::shared_ptr<EncodedFrame> encode(JpegEncoder& encoder, ServiceStats& stats);
};

}  // namespace geodesic
