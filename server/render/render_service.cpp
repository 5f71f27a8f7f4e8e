#include "render/render_service.h"

#include "render/pipeline_cache.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>

#include "render/jpeg_encoder.h"
#include "render/render_session.h"
#include "render/renderer.h"
#include "render/session_rota.h"
#include "render/vulkan_context.h"
#include "scene/scene_loader.h"

namespace geodesic {
namespace {

using Clock = std::chrono::steady_clock;

constexpr auto kSlice = std::chrono::duration_cast<Clock::duration>(
    std::chrono::duration<double>(RenderService::kSliceSeconds));

// After a device loss, a new device is tried at most this often.
constexpr auto kDeviceRetry = std::chrono::seconds(1);

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

}  // namespace

PreparedScene::PreparedScene() = default;
PreparedScene::~PreparedScene() = default;
PreparedScene::PreparedScene(PreparedScene&&) noexcept = default;
PreparedScene& PreparedScene::operator=(PreparedScene&&) noexcept = default;

using Session = RenderSession;

struct RenderService::Impl {
  const std::string device_selector;
  std::unique_ptr<VulkanContext> ctx;
  std::filesystem::path pipeline_cache_dir;  // kept for a replacement device
  // Devices lost so far, kept until the service ends: render jobs may still hold renderers made
  // on them, which free their objects through them.
  std::vector<std::unique_ptr<VulkanContext>> lost_devices;
  Clock::time_point next_device_attempt;
  std::string scene_dir;
  ServiceLimits limits;
  JpegEncoder encoder;

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
  // Callers of run_beside working on the device now: the service ends after them.
  mutable int beside = 0;
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

  Impl(const std::string& device, std::string dir, ServiceLimits l)
      : device_selector(device),
        ctx(std::make_unique<VulkanContext>(device)),
        scene_dir(std::move(dir)),
        limits(l) {
    stats.device = ctx->description().name;
    publish();
    thread = std::thread([this] { run(); });
  }

  ~Impl() {
    {
      std::lock_guard lock(mutex);
      stopping = true;
    }
    wake.notify_all();
    background_turn.notify_all();
    replaced.notify_all();
    thread.join();
    std::unique_lock lock(mutex);
    beside_done.wait(lock, [this] { return beside == 0; });
  }

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
  void run() {
    std::unique_lock lock(mutex);
    while (!stopping) {
      // A session's or a job's submission lost the device: replace it before anyone renders on
      // the lost one (which would fail whichever session came next).
      if (ctx->lost()) replace_lost_device();
      auto it = rota.next(sessions);
      if (it == sessions.end()) {
        // Between rounds: a background turn, or a pause when there is nothing to do.
        const bool handed_over = hand_over_background(lock);
        if (ctx->lost()) replace_lost_device();
        it = rota.next(sessions);
        if (it == sessions.end() && !handed_over)
          wake.wait_for(lock, std::chrono::milliseconds(50));
      }
      Clock::duration refining{};  // a slice that no one waits for
      if (it != sessions.end()) {
        stats.queue_depth = int(sessions.size()) - 1;
        const auto slice_start = Clock::now();
        try {
          serve(*it->second);
        } catch (const std::exception& e) {  // its renderer may be half-way through a pass
          fail(it->first, std::string("render: ") + e.what());
        }
        if (!rota.out_of_turn()) refining = Clock::now() - slice_start;
      }
      // A scene being prepared beside (a client waits for it, on threads below this one's
      // priority) gets the processor for as long again as a refining slice took.
      const auto step_aside = beside > 0 ? std::min(refining, kSlice) : Clock::duration{};
      // Let waiting callers (moves, new scenes) in between slices.
      publish();
      lock.unlock();
      std::this_thread::sleep_for(step_aside);
      for (int spins = 0; waiting.load() > 0 && spins < 100; ++spins)
        std::this_thread::sleep_for(std::chrono::microseconds(100));
      lock.lock();
    }
  }

  // Closes a session whose render failed; its client hears why.
  void fail(SessionId id, const std::string& reason) {
    auto session = sessions.extract(id);
    stats.sessions = int(sessions.size());
    std::fprintf(stderr, "geodesic: session %llu closed: %s\n",
                 static_cast<unsigned long long>(id), reason.c_str());
    if (session.mapped()->on_failure) session.mapped()->on_failure(reason);
  }

  // A lost device can only have its objects destroyed: the sessions' renderers go, a new device
  // is made with the same selector, and every session gets a new renderer on it at its own
  // scene, view and settings (accumulation starts over). Render jobs find their renderers'
  // device lost at their next turn and start over from their checkpoints (jobs/job_runner.h).
  void replace_lost_device() {
    if (Clock::now() < next_device_attempt) return;
    next_device_attempt = Clock::now() + kDeviceRetry;
    std::unique_ptr<VulkanContext> fresh;
    try {
      fresh = std::make_unique<VulkanContext>(device_selector);
      fresh->pipeline_cache().set_directory(pipeline_cache_dir);
    } catch (const std::exception& e) {  // sessions fail on the lost one until a retry works
      std::fprintf(stderr, "geodesic: Vulkan device lost, no new one yet: %s\n", e.what());
      return;
    }
    for (auto& [id, s] : sessions) s->renderer.reset();
    lost_devices.push_back(std::exchange(ctx, std::move(fresh)));
    replaced.notify_all();
    std::fprintf(stderr, "geodesic: Vulkan device lost; rendering on a new %s device\n",
                 ctx->description().name.c_str());
    std::vector<std::pair<SessionId, std::string>> failed;
    for (auto& [id, s] : sessions) {
      try {
        s->renderer = std::make_unique<Renderer>(*ctx, s->scene);
        s->restart(false);
      } catch (const std::exception& e) {
        failed.emplace_back(id, std::string("render: on the new device: ") + e.what());
      }
    }
    for (const auto& [id, reason] : failed) fail(id, reason);
  }

  // Gives the device to the first background caller for one turn unless a session is moving;
  // true when one had it.
  bool hand_over_background(std::unique_lock<std::mutex>& lock) {
    if (background_queue.empty()) return false;
    for (const auto& [id, s] : sessions)
      if (s->moving) return false;
    granted = background_queue.front();
    background_queue.pop_front();
    background_turn.notify_all();
    background_turn.wait(lock, [this] { return granted == 0; });
    return true;
  }

  // One slice of the session's pass; its frame goes out when the pass is complete.
  void serve(Session& s) {
    auto frame = s.serve(encoder, stats, recent_samples);
    const double window = seconds_since(window_start);
    if (window > 1.0) {
      stats.samples_per_second = recent_samples / window;
      recent_samples = 0;
      window_start = Clock::now();
    }
    if (frame) s.on_frame(std::move(frame));
  }
};

RenderService::RenderService(const std::string& device, std::string scene_dir,
                             ServiceLimits limits)
    : impl_(std::make_unique<Impl>(device, std::move(scene_dir), limits)) {}

RenderService::~RenderService() = default;

void RenderService::use_pipeline_cache(const std::filesystem::path& dir) {
  std::lock_guard lock(impl_->mutex);
  impl_->pipeline_cache_dir = dir;
  impl_->ctx->pipeline_cache().set_directory(dir);
}

std::vector<std::string> RenderService::bundled_scenes() const {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(impl_->scene_dir))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

const ServiceLimits& RenderService::limits() const { return impl_->limits; }

PreparedScene RenderService::prepare_scene(Scene scene, std::string name) const {
  impl_->check_limits(scene);
  PreparedScene prepared;
  // A device lost during the build: build again on its replacement (a lost device keeps
  // failing, so this ends).
  for (int attempt = 0; attempt < 2 && !(prepared.renderer && !prepared.renderer->context().lost());
       ++attempt) {
    prepared.renderer.reset();
    if (!run_beside([&](VulkanContext& ctx) { prepared.renderer = std::make_unique<Renderer>(ctx, scene); }))
      throw std::runtime_error("render: the server is stopping");
  }
  prepared.scene = std::move(scene);
  prepared.name = std::move(name);
  return prepared;
}

PreparedScene RenderService::prepare_bundled_scene(const std::string& name) const {
  return prepare_scene(load_bundled_scene(name), name);
}

RenderService::SessionId RenderService::open_session(PreparedScene&& scene, FrameCallback on_frame,
                                                     FailureCallback on_failure) {
  auto lock = impl_->lock();
  if (int(impl_->sessions.size()) >= impl_->limits.max_sessions)
    throw std::runtime_error("too many sessions (" + std::to_string(impl_->limits.max_sessions) +
                             " open)");
  if (!impl_->current(*scene.renderer)) {  // built on a device lost since
    lock.unlock();
    scene = prepare_scene(std::move(scene.scene), std::move(scene.name));
    return open_session(std::move(scene), std::move(on_frame), std::move(on_failure));
  }
  auto session = std::make_unique<Session>();
  session->on_frame = std::move(on_frame);
  session->on_failure = std::move(on_failure);
  session->adopt(std::move(scene));
  const SessionId id = impl_->next_id++;
  impl_->sessions[id] = std::move(session);
  impl_->stats.sessions = int(impl_->sessions.size());
  impl_->publish();
  impl_->wake.notify_all();
  return id;
}

RenderService::SessionId RenderService::open_session(FrameCallback on_frame,
                                                     FailureCallback on_failure) {
  return open_session(prepare_bundled_scene("cornell-box"), std::move(on_frame),
                      std::move(on_failure));
}

void RenderService::close_session(SessionId id) {
  auto lock = impl_->lock();
  impl_->sessions.erase(id);  // frees its renderer and buffers
  impl_->stats.sessions = int(impl_->sessions.size());
  impl_->publish();
}

Scene RenderService::load_bundled_scene(const std::string& name) const {
  const auto names = bundled_scenes();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw SceneError("scene: unknown bundled scene \"" + name + "\"");
  return load_scene_file(std::filesystem::path(impl_->scene_dir) / (name + ".json"));
}

Scene RenderService::parse_scene_document(const nlohmann::ordered_json& document) const {
  return parse_scene(document, DocumentFiles(impl_->scene_dir, /*confined=*/true));
}

SceneInfo RenderService::load_scene(SessionId id, const std::string& name) {
  return install_scene(id, load_bundled_scene(name), name);
}

SceneInfo RenderService::load_scene_document(SessionId id, const nlohmann::ordered_json& doc) {
  Scene scene = parse_scene_document(doc);
  std::string name = scene.name.empty() ? "document" : scene.name;
  return install_scene(id, std::move(scene), std::move(name));
}

SceneInfo RenderService::install_scene(SessionId id, Scene scene, std::string name) {
  return install_scene(id, prepare_scene(std::move(scene), std::move(name)));
}

SceneInfo RenderService::install_scene(SessionId id, PreparedScene&& scene) {
  auto lock = impl_->lock();
  Session& s = impl_->find(id);
  if (!impl_->current(*scene.renderer)) {  // built on a device lost since
    lock.unlock();
    return install_scene(id, std::move(scene.scene), std::move(scene.name));
  }
  auto old = std::move(s.renderer);  // freed after the lock
  s.adopt(std::move(scene));
  SceneInfo info = s.info();
  lock.unlock();
  return info;
}

void RenderService::move_camera(SessionId id, const CameraMotion& motion) {
  auto lock = impl_->lock();
  Session& s = impl_->find(id);
  const Mat4 pose = apply_motion(s.scene.geometry, s.pose, motion);
  // The pose stays finite whatever the move: one that would not is refused, the pose kept.
  if (!(model::isometry_error(s.scene.geometry, pose) < 1e-6))
    throw std::invalid_argument("move: the camera would leave the space's model (a step too long)");
  s.pose = pose;
  s.last_move = Clock::now();
  s.restart(true);
}

SceneInfo RenderService::apply_settings(SessionId id, const SessionSettings& settings) {
  if (auto resized = prepare_settings(id, settings)) install_scene(id, std::move(*resized));
  auto lock = impl_->lock();
  Session& s = impl_->find(id);
  const int width = settings.width ? settings.width : s.width;
  const int height = settings.height ? settings.height : s.height;
  if (width > s.scene.render.width || height > s.scene.render.height) {
    lock.unlock();  // another scene came in between: build again
    return apply_settings(id, settings);
  }
  s.width = width;
  s.height = height;
  if (settings.max_depth != -1) {
    s.scene.render.max_depth = settings.max_depth;
    s.renderer->set_max_depth(settings.max_depth);
  }
  if (settings.exposure) s.set_exposure(*settings.exposure);
  const bool view_changed = settings.width || settings.height || settings.max_depth != -1;
  if (view_changed || !settings.exposure) s.restart(false);
  return s.info();
}

std::optional<PreparedScene> RenderService::prepare_settings(SessionId id,
                                                             const SessionSettings& settings) const {
  const ServiceLimits& l = impl_->limits;
  if (settings.width != 0 && (settings.width < 16 || settings.width > l.max_width))
    throw std::invalid_argument("width: must be in [16, " + std::to_string(l.max_width) + "]");
  if (settings.height != 0 && (settings.height < 16 || settings.height > l.max_height))
    throw std::invalid_argument("height: must be in [16, " + std::to_string(l.max_height) + "]");
  if (settings.max_depth != -1 && (settings.max_depth < 0 || settings.max_depth > l.max_depth))
    throw std::invalid_argument("max_depth: must be in [0, " + std::to_string(l.max_depth) + "]");
  Scene scene;
  std::string name;
  {
    auto lock = impl_->lock();
    Session& s = impl_->find(id);
    const int width = settings.width ? settings.width : s.width;
    const int height = settings.height ? settings.height : s.height;
    if (width <= s.scene.render.width && height <= s.scene.render.height) return std::nullopt;
    scene = s.scene;  // the renderer is rebuilt at the new size, from the camera's pose
    name = s.scene_name;
    scene.render.width = std::max(s.scene.render.width, width);
    scene.render.height = std::max(s.scene.render.height, height);
    scene.camera.pose = s.pose;
  }
  return prepare_scene(std::move(scene), std::move(name));
}

bool RenderService::run_background(const std::function<void(VulkanContext&)>& work) {
  Impl& impl = *impl_;
  std::unique_lock lock(impl.mutex);  // not impl.lock(): that one has priority
  if (impl.stopping) return false;
  const uint64_t ticket = impl.next_ticket++;
  impl.background_queue.push_back(ticket);
  impl.wake.notify_all();
  impl.background_turn.wait(lock, [&] { return impl.granted == ticket || impl.stopping; });
  if (impl.granted != ticket) {
    std::erase(impl.background_queue, ticket);
    return false;
  }
  struct GiveBack {  // the device goes back to the render thread, even when `work` throws
    Impl& impl;
    ~GiveBack() {
      impl.granted = 0;
      impl.background_turn.notify_all();
    }
  } give_back{impl};
  work(*impl.ctx);
  return true;
}

bool RenderService::settings_fit(SessionId id, const SessionSettings& settings) const {
  auto lock = impl_->lock();
  const Session& s = impl_->find(id);
  return (settings.width ? settings.width : s.width) <= s.scene.render.width &&
         (settings.height ? settings.height : s.height) <= s.scene.render.height;
}

bool RenderService::run_beside(const std::function<void(VulkanContext&)>& work) const {
  Impl& impl = *impl_;
  VulkanContext* device = nullptr;
  {
    auto lock = impl.lock();
    // A lost device is replaced by the render thread: build on its successor (a while for one
    // to be made; then on the lost one, whose submissions fail with the reason).
    if (impl.ctx->lost()) {
      impl.wake.notify_all();
      impl.replaced.wait_for(lock, 2 * kDeviceRetry,
                             [&] { return impl.stopping || !impl.ctx->lost(); });
    }
    if (impl.stopping) return false;
    device = impl.ctx.get();  // stays valid: lost devices are kept until the service ends
    ++impl.beside;
  }
  struct Done {
    Impl& impl;
    ~Done() {
      std::lock_guard lock(impl.mutex);
      if (--impl.beside == 0) impl.beside_done.notify_all();
    }
  } done{impl};
  work(*device);
  return true;
}

void RenderService::count_background(uint64_t non_finite_samples, uint64_t truncated_geodesics) {
  std::lock_guard lock(impl_->mutex);
  impl_->stats.non_finite_samples += non_finite_samples;
  impl_->stats.truncated_geodesics += truncated_geodesics;
  impl_->publish();
}

ServiceStats RenderService::stats() const {
  std::lock_guard hold(impl_->published_mutex);
  return impl_->published;
}

}  // namespace geodesic
