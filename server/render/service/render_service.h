// The daemon's renderer: owns the Vulkan device and one render thread that serves every session
// in turn (round-robin, a time slice each, so no session starves another; a session whose new
// view awaits its first frame goes in between, every other slice at most), keeps each session's
// scene, camera, settings and accumulation, and hands each new JPEG frame to the session's
// callback. Thread-safe: every public function may be called from any thread.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/vec.h"
#include "scene/camera_motion.h"
#include "scene/scene.h"
#include "scene/scene_source.h"

namespace geodesic {

class VulkanContext;

struct FrameInfo {
  uint64_t frame = 0;     // per session, increasing
  uint32_t spp = 0;       // samples per pixel so far
  double elapsed = 0;     // seconds since the last reset
  double error = -1;      // estimated relative RMS error; < 0 while unknown
  int width = 0, height = 0;
  bool moving = false;    // reduced resolution right after a move
  double exposure = 0;    // the stops applied (the automatic exposure's, when automatic)
  Mat4 camera;            // the camera isometry
  // Since the session's scene was loaded: samples dropped as NaN/Inf, and geodesics cut off at
  // the scene's max_crossings (they return black: docs/light-transport.md).
  uint64_t non_finite_samples = 0, truncated_geodesics = 0;
};

struct EncodedFrame {
  FrameInfo info;
  std::vector<unsigned char> jpeg;
};

// What the protocol's `scene` message says of a session's scene: `name` as ResolvedScene has
// it (the bundled name, the document's name or "document"), `source` how it was given
// (source_kind_name), `title` the document's own name (its name when it has none).
struct SceneInfo {
  std::string name, geometry, manifold;
  int width = 0, height = 0, max_depth = 0;
  Exposure exposure;
  std::string source = source_kind_name(SceneSource::Kind::Bundled), title;
};

// Absent fields keep their value. A new exposure alone keeps the accumulation: the last frame
// comes again at once with it.
struct SessionSettings {
  int width = 0, height = 0, max_depth = -1;
  std::optional<Exposure> exposure;
};

struct ServiceStats {
  int sessions = 0;
  uint64_t frames = 0;            // encoded, all sessions
  double samples_per_second = 0;  // pixel samples per second, recent
  double encode_seconds_sum = 0;  // total JPEG encode time
  uint64_t encode_count = 0;
  int queue_depth = 0;            // sessions waiting for the render thread
  uint64_t non_finite_samples = 0;   // dropped as NaN/Inf, every session and job so far
  uint64_t truncated_geodesics = 0;  // cut off at max_crossings, every session and job so far
  std::string device;
};

struct ServiceLimits {
  int max_sessions = 16;
  int max_width = 1920, max_height = 1080, max_depth = 16;
};

class Renderer;

// A scene with its renderer built: the expensive part of showing a scene (domain cells,
// acceleration structures, the pipeline), made by RenderService::prepare_scene on any thread
// and outside the device lock, so that installing it in a session is cheap.
struct PreparedScene {
  PreparedScene();
  ~PreparedScene();
  PreparedScene(PreparedScene&&) noexcept;
  PreparedScene& operator=(PreparedScene&&) noexcept;
  Scene scene;
  std::string name;
  SceneSource::Kind kind = SceneSource::Kind::Bundled;
  std::unique_ptr<Renderer> renderer;
};

class RenderService {
 public:
  using SessionId = uint64_t;
  // Called on a frame-encoding thread with each new frame of the session, in order (a frame
  // still waiting when a newer pass completes is dropped for it, and none comes once
  // close_session has returned); it must return quickly and must not call back into the
  // service (hand the frame to another thread).
  using FrameCallback = std::function<void(std::shared_ptr<const EncodedFrame>)>;
  // Called on the render thread, as FrameCallback, when rendering the session failed (a Vulkan
  // error such as VK_ERROR_DEVICE_LOST or VK_ERROR_OUT_OF_DEVICE_MEMORY): the session is closed
  // already, and the reason names the error.
  using FailureCallback = std::function<void(const std::string& reason)>;

  // device: as --device; scene_dir: where bundled scenes live. Throws VulkanError.
  RenderService(const std::string& device, std::string scene_dir, ServiceLimits limits = {});
  ~RenderService();
  RenderService(const RenderService&) = delete;
  RenderService& operator=(const RenderService&) = delete;

  // Keeps compiled pipelines in `dir` too (render/device/pipeline_cache.h), so that a restarted daemon
  // compiles nothing it compiled before.
  void use_pipeline_cache(const std::filesystem::path& dir);

  std::vector<std::string> bundled_scenes() const;
  const ServiceLimits& limits() const;

  // Resolves `source` (scene/scene_source.h) against this service's scene directory: bundled
  // scenes are its files, and an inline document's file names must lie inside it. Throws
  // SceneError ("<field>: <reason>").
  ResolvedScene resolve(const SceneSource& source) const;

  // Builds the scene's renderer on the calling thread, beside the rendering (not under the
  // device lock): the daemon calls it on its preparation pool, never on an I/O thread. Throws
  // SceneError when the scene is bad or exceeds the server's limits.
  PreparedScene prepare_scene(ResolvedScene scene) const;
  PreparedScene prepare_scene(const SceneSource& source) const;

  // A CPU device (lavapipe) compiles a pipeline's code at its first dispatch, not when the
  // pipeline is made, and holds the one queue that every session and job shares meanwhile (a
  // second for a scene of 500 lights, when Mesa's shader cache does not have it yet). This
  // compiles the pipeline of `renderer` (built for `scene`) once, by a dispatch of one pixel on
  // a device of the service's own beside the shared one: the code reaches the shared device's
  // first dispatch through Mesa's shader cache. Nothing to do on a GPU, which compiles when the
  // pipeline is made. Beside the rendering: prepare_scene and render jobs call it, never the
  // render thread.
  void warm_up(const Renderer& renderer, const Scene& scene) const;

  // Opens a session on `scene` (the client's first view: the daemon prepares
  // kDefaultSceneName);
  // throws std::runtime_error when max_sessions are open, leaving `scene` as it was. A failed
  // render ends only its own session; after a device loss the service makes a new device and
  // the other sessions go on, their accumulation started over.
  SessionId open_session(PreparedScene&& scene, FrameCallback on_frame,
                         FailureCallback on_failure = nullptr);
  // The same on kDefaultSceneName, prepared on the calling thread.
  SessionId open_session(FrameCallback on_frame, FailureCallback on_failure = nullptr);
  void close_session(SessionId id);

  // Each throws geodesic::SceneError / std::invalid_argument ("<field>: <reason>") on bad
  // input, leaving the session as it was. The scene's renderer is built on the calling thread.
  SceneInfo load_scene(SessionId id, const SceneSource& source);
  SceneInfo load_scene(SessionId id, const std::string& bundled_name);
  SceneInfo load_scene_document(SessionId id, const nlohmann::ordered_json& document);
  // A prepared scene: cheap (a renderer built on a device lost since is built again here).
  SceneInfo install_scene(SessionId id, PreparedScene&& scene);
  void move_camera(SessionId id, const CameraMotion& motion);
  // In a space without a quotient the renderer works in a frame centred on the camera it was
  // built at (render/device/renderer.h). True when `motion` takes the camera so far from it that a
  // renderer built at the moved camera should take over: prepare_move builds it, beside the
  // rendering; move the camera, then rebase(id, prepared).
  bool move_outgrows_frame(SessionId id, const CameraMotion& motion) const;
  PreparedScene prepare_move(SessionId id, const CameraMotion& motion) const;
  // The session goes on with the prepared renderer, its scene, view and settings unchanged
  // (accumulation starts over, as after any move).
  void rebase(SessionId id, PreparedScene&& prepared);
  // Settings larger than the session's buffers need a new renderer, built on the calling
  // thread; prepare_settings builds it beforehand (nullopt when the buffers are large enough):
  // install it, then apply the settings.
  SceneInfo apply_settings(SessionId id, const SessionSettings& settings);
  std::optional<PreparedScene> prepare_settings(SessionId id, const SessionSettings& settings) const;
  // True when the session's buffers hold the settings' size: apply_settings is cheap.
  bool settings_fit(SessionId id, const SessionSettings& settings) const;

  ServiceStats stats() const;
  // Adds a render job's new non-finite samples and truncated geodesics to stats().
  void count_background(uint64_t non_finite_samples, uint64_t truncated_geodesics);

  // Low-priority work (render jobs): waits until the render thread hands over the device, then
  // runs `work(device)` on the calling thread with the device to itself. A hand-over happens
  // once per round of the sessions, and never while a session is moving, so walking keeps its
  // frame rate; with no session open, background callers take turns back to back. `work`
  // should take about one slice (kSliceSeconds). Returns false, without running `work`, once
  // the service is stopping.
  static constexpr double kSliceSeconds = 0.04;
  bool run_background(const std::function<void(VulkanContext&)>& work);
  // Runs `work(device)` on the calling thread with the service's current device at once,
  // beside the rendering and outside the device lock: for building and freeing renderers, which
  // the device allows from any thread (render/device/vulkan_context.h). Returns false, without running
  // `work`, once the service is stopping.
  bool run_beside(const std::function<void(VulkanContext&)>& work) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace geodesic
