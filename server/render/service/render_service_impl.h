// RenderService's state, shared by render_service.cpp (the public functions) and
// render_thread.cpp (the render thread: slices, device loss, background turns). Private to
// those two files.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "render/service/frame_encoder.h"
#include "render/service/render_service.h"
#include "render/service/render_session.h"
#include "render/device/renderer.h"
#include "render/service/session_rota.h"
#include "render/device/vulkan_context.h"

namespace geodesic {

using Session = RenderSession;

struct RenderService::Impl {
  using Clock = std::chrono::steady_clock;
  // After a device loss, a new device is tried at most this often.
  static constexpr auto kDeviceRetry = std::chrono::seconds(1);

  const std::string device_selector;
  std::unique_ptr<VulkanContext> ctx;
  std::filesystem::path pipeline_cache_dir;  // kept for a replacement device
  // Devices lost so far, kept until the service ends: render jobs may still hold renderers made
  // on them, which free their objects through them.
  std::vector<std::unique_ptr<VulkanContext>> lost_devices;
  Clock::time_point next_device_attempt;
  std::string scene_dir;
  ServiceLimits limits;
  // Resolves and encodes the sessions' passes beside the render thread, outside the lock.
  FrameEncoder frames;

  mutable std::mutex mutex;  // guards everything below and all rendering
  // Callers waiting for the mutex: the render thread steps aside for them between slices, so
  // a move, a new scene or /metrics waits at most one slice.
  mutable std::atomic<int> waiting{0};
  std::condition_variable wake;
  // Notified when the render thread has replaced a lost device.
  mutable std::condition_variable replaced;
  // Background callers (run_background) wait in arrival order for a turn; `granted` is the
  // ticket holding the device, 0 when the render thread has it.
  std::condition_variable background_turn;
  std::deque<uint64_t> background_queue;
  uint64_t next_ticket = 1, granted = 0;
  SessionRota::Sessions sessions;
  SessionId next_id = 1;
  SessionRota rota;
  bool stopping = false;
  // warm_up's device (made on first use) and the lock its one queue is used under.
  mutable std::mutex warm_mutex;
  mutable std::unique_ptr<VulkanContext> warm_device;
  // Callers of run_beside working on the device now: the service ends after them.
  mutable int beside = 0;
  // Scenes being prepared (resolved, built, their pipelines compiled ahead) on threads below the
  // render thread's priority: while there are any, the render thread steps aside after each
  // refining slice, so that lavapipe's threads do not starve them (render_thread.cpp).
  mutable std::atomic<int> preparing{0};
  mutable std::condition_variable beside_done;
  ServiceStats stats;
  // A copy of `stats` for stats(): /healthz and /metrics never wait for the device lock.
  mutable std::mutex published_mutex;
  ServiceStats published;
  void publish() {
    std::lock_guard hold(published_mutex);
    published = stats;
  }
  double recent_samples = 0;
  Clock::time_point window_start = Clock::now();
  std::thread thread;

  Impl(const std::string& device, std::string dir, ServiceLimits l);
  ~Impl();

  std::unique_lock<std::mutex> lock() const {
    ++waiting;
    std::unique_lock<std::mutex> held(mutex);
    --waiting;
    return held;
  }

  Session& find(SessionId id) {
    auto it = sessions.find(id);
    if (it == sessions.end()) throw std::invalid_argument("session: no such session");
    return *it->second;
  }

  void check_limits(const Scene& scene) const {
    if (scene.render.width > limits.max_width)
      throw SceneError("render.width: must be <= " + std::to_string(limits.max_width) + " on this server");
    if (scene.render.height > limits.max_height)
      throw SceneError("render.height: must be <= " + std::to_string(limits.max_height) + " on this server");
    if (scene.render.max_depth > limits.max_depth)
      throw SceneError("render.max_depth: must be <= " + std::to_string(limits.max_depth) + " on this server");
  }

  // True when `renderer` was built on the current device (not on one lost since).
  bool current(const Renderer& renderer) const { return &renderer.context() == ctx.get(); }

  // The render thread: one slice at a time, to the session the rota names.
  void run();

  // Closes a session whose render failed; its client hears why, and gets no frame after.
  void fail(SessionId id, const std::string& reason);

  // A lost device can only have its objects destroyed: the sessions' renderers go, a new device
  // is made with the same selector, and every session gets a new renderer on it at its own
  // scene, view and settings (accumulation starts over). Render jobs find their renderers'
  // device lost at their next turn and start over from their checkpoints (jobs/job_runner.h).
  void replace_lost_device();

  // Gives the device to the first background caller for one turn unless a session is moving;
  // true when one had it.
  bool hand_over_background(std::unique_lock<std::mutex>& lock);

  // One slice of the session's pass; when the pass is complete, its frame goes to the
  // session's stream.
  void serve(Session& s);
};

}  // namespace geodesic
