// The daemon's renderer: owns the Vulkan device and one render thread that serves every session
// in turn (round-robin, a time slice each, so no session starves another), keeps each session's
// scene, camera, settings and accumulation, and hands each new JPEG frame to the session's
// callback. Thread-safe: every public function may be called from any thread.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/vec.h"
#include "scene/camera_motion.h"
#include "scene/scene.h"

namespace geodesic {

class VulkanContext;

struct FrameInfo {
  uint64_t frame = 0;     // per session, increasing
  uint32_t spp = 0;       // samples per pixel so far
  double elapsed = 0;     // seconds since the last reset
  double error = -1;      // estimated relative RMS error; < 0 while unknown
  int width = 0, height = 0;
  bool moving = false;    // reduced resolution right after a move
  Mat4 camera;            // the camera isometry
  // Since the session's scene was loaded: samples dropped as NaN/Inf, and geodesics cut off at
  // the scene's max_crossings (they return black: docs/light-transport.md).
  uint64_t non_finite_samples = 0, truncated_geodesics = 0;
};

struct EncodedFrame {
  FrameInfo info;
  std::vector<unsigned char> jpeg;
};

struct SceneInfo {
  std::string name, geometry, manifold;
  int width = 0, height = 0, max_depth = 0;
};

// Absent fields keep their value.
struct SessionSettings {
  int width = 0, height = 0, max_depth = -1;
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

class RenderService {
 public:
  using SessionId = uint64_t;
  // Called on the render thread with each new frame of the session; it must return quickly and
  // must not call back into the service (hand the frame to another thread).
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

  // Keeps compiled pipelines in `dir` too (render/pipeline_cache.h), so that a restarted daemon
  // compiles nothing it compiled before.
  void use_pipeline_cache(const std::filesystem::path& dir);

  std::vector<std::string> bundled_scenes() const;
  const ServiceLimits& limits() const;

  // Opens a session on the default scene ("cornell-box"); throws std::runtime_error when
  // max_sessions are open. A failed render ends only its own session; after a device loss the
  // service makes a new device and the other sessions go on, their accumulation started over.
  SessionId open_session(FrameCallback on_frame, FailureCallback on_failure = nullptr);
  void close_session(SessionId id);

  // A bundled scene by name, or an inline scene document (mesh paths relative to the scene
  // directory), as `open` resolves them; throws SceneError ("<field>: <reason>").
  Scene load_bundled_scene(const std::string& name) const;
  Scene parse_scene_document(const nlohmann::ordered_json& document) const;

  // Each throws geodesic::SceneError / std::invalid_argument ("<field>: <reason>") on bad
  // input, leaving the session as it was.
  SceneInfo load_scene(SessionId id, const std::string& bundled_name);
  SceneInfo load_scene_document(SessionId id, const nlohmann::ordered_json& document);
  // A scene prepared beforehand (load_bundled_scene, parse_scene_document: the daemon does
  // that off its I/O threads), shown as `name`.
  SceneInfo install_scene(SessionId id, Scene scene, std::string name);
  void move_camera(SessionId id, const CameraMotion& motion);
  SceneInfo apply_settings(SessionId id, const SessionSettings& settings);

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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace geodesic
