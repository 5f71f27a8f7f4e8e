#include "render/service/render_service.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "render/device/pipeline_cache.h"
#include "render/service/render_service_impl.h"
#include "scene/camera_motion.h"

namespace geodesic {
namespace {

// Counts a scene preparation for the render thread's stepping aside, for as long as it runs.
class Preparing {
 public:
  explicit Preparing(std::atomic<int>& count) : count_(count) { ++count_; }
  ~Preparing() { --count_; }
  Preparing(const Preparing&) = delete;
  Preparing& operator=(const Preparing&) = delete;

 private:
  std::atomic<int>& count_;
};

}  // namespace

PreparedScene::PreparedScene() = default;
PreparedScene::~PreparedScene() = default;
PreparedScene::PreparedScene(PreparedScene&&) noexcept = default;
PreparedScene& PreparedScene::operator=(PreparedScene&&) noexcept = default;

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
  return bundled_scene_names(impl_->scene_dir);
}

const ServiceLimits& RenderService::limits() const { return impl_->limits; }

ResolvedScene RenderService::resolve(const SceneSource& source) const {
  return resolve_scene(source, impl_->scene_dir);
}

PreparedScene RenderService::prepare_scene(ResolvedScene resolved) const {
  const Preparing preparing(impl_->preparing);
  Scene& scene = resolved.scene;
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
  warm_up(*prepared.renderer, scene);
  prepared.scene = std::move(scene);
  prepared.name = std::move(resolved.name);
  prepared.kind = resolved.kind;
  return prepared;
}

void RenderService::warm_up(const Renderer& renderer, const Scene& scene) const {
  if (!renderer.context().description().cpu || renderer.backend().pipeline().warmed.exchange(true))
    return;
  std::lock_guard hold(impl_->warm_mutex);
  try {
    if (!impl_->warm_device) impl_->warm_device = std::make_unique<VulkanContext>(impl_->device_selector);
    Scene pixel = scene;
    pixel.render.width = pixel.render.height = 1;
    Renderer warm(*impl_->warm_device, pixel);
    warm.add_samples(1);
  } catch (const std::exception& e) {  // only time is lost: the first dispatch compiles it
    std::fprintf(stderr, "geodesic: could not compile a pipeline ahead: %s\n", e.what());
  }
}

PreparedScene RenderService::prepare_scene(const SceneSource& source) const {
  const Preparing preparing(impl_->preparing);  // the group enumeration too
  return prepare_scene(resolve(source));
}

RenderService::SessionId RenderService::open_session(PreparedScene&& scene, FrameCallback on_frame,
                                                     FailureCallback on_failure) {
  auto lock = impl_->lock();
  if (int(impl_->sessions.size()) >= impl_->limits.max_sessions)
    throw std::runtime_error("too many sessions (" + std::to_string(impl_->limits.max_sessions) +
                             " open)");
  if (!impl_->current(*scene.renderer)) {  // built on a device lost since
    lock.unlock();
    scene = prepare_scene(ResolvedScene{std::move(scene.scene), scene.kind, std::move(scene.name), {}});
    return open_session(std::move(scene), std::move(on_frame), std::move(on_failure));
  }
  auto session = std::make_unique<Session>();
  session->stream = impl_->frames.open(std::move(on_frame));
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
  return open_session(prepare_scene(SceneSource::bundled(kDefaultSceneName)), std::move(on_frame),
                      std::move(on_failure));
}

void RenderService::close_session(SessionId id) {
  auto lock = impl_->lock();
  auto it = impl_->sessions.find(id);
  if (it == impl_->sessions.end()) return;
  impl_->frames.close(*it->second->stream);  // no frame of it comes after this
  impl_->sessions.erase(it);                 // frees its renderer and buffers
  impl_->stats.sessions = int(impl_->sessions.size());
  impl_->publish();
}

SceneInfo RenderService::load_scene(SessionId id, const SceneSource& source) {
  return install_scene(id, prepare_scene(source));
}

SceneInfo RenderService::load_scene(SessionId id, const std::string& name) {
  return load_scene(id, SceneSource::bundled(name));
}

SceneInfo RenderService::load_scene_document(SessionId id, const nlohmann::ordered_json& doc) {
  return load_scene(id, SceneSource::inline_document(doc));
}

SceneInfo RenderService::install_scene(SessionId id, PreparedScene&& scene) {
  auto lock = impl_->lock();
  Session& s = impl_->find(id);
  if (!impl_->current(*scene.renderer)) {  // built on a device lost since
    lock.unlock();
    return install_scene(id, prepare_scene(ResolvedScene{std::move(scene.scene), scene.kind,
                                                         std::move(scene.name), {}}));
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
  if (!(model::relative_isometry_error(s.scene.geometry, pose) < 1e-6))
    throw std::invalid_argument("move: the camera would leave the space's model (a step too long)");
  s.pose = pose;
  s.last_move = Impl::Clock::now();
  s.restart(true);
}

bool RenderService::move_outgrows_frame(SessionId id, const CameraMotion& motion) const {
  auto lock = impl_->lock();
  const Session& s = impl_->find(id);
  return s.renderer->frame_outgrown(apply_motion(s.scene.geometry, s.pose, motion));
}

PreparedScene RenderService::prepare_move(SessionId id, const CameraMotion& motion) const {
  ResolvedScene resolved;
  {
    auto lock = impl_->lock();
    const Session& s = impl_->find(id);
    resolved = {s.scene, s.scene_kind, s.scene_name, {}};
    resolved.scene.camera.pose = apply_motion(s.scene.geometry, s.pose, motion);
  }
  return prepare_scene(std::move(resolved));
}

void RenderService::rebase(SessionId id, PreparedScene&& prepared) {
  auto lock = impl_->lock();
  Session& s = impl_->find(id);
  if (!impl_->current(*prepared.renderer)) return;  // the device was lost: the old frame serves
  auto old = std::move(s.renderer);                 // freed after the lock
  s.rebase(std::move(prepared.renderer));
  lock.unlock();
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
  // A new depth reaches the renderer through the restart below.
  if (settings.max_depth != -1) s.scene.render.max_depth = settings.max_depth;
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
  ResolvedScene resolved;
  {
    auto lock = impl_->lock();
    Session& s = impl_->find(id);
    const int width = settings.width ? settings.width : s.width;
    const int height = settings.height ? settings.height : s.height;
    if (width <= s.scene.render.width && height <= s.scene.render.height) return std::nullopt;
    // The renderer is rebuilt at the new size, from the camera's pose.
    resolved = {s.scene, s.scene_kind, s.scene_name, {}};
    resolved.scene.render.width = std::max(s.scene.render.width, width);
    resolved.scene.render.height = std::max(s.scene.render.height, height);
    resolved.scene.camera.pose = s.pose;
  }
  return prepare_scene(std::move(resolved));
}

bool RenderService::run_background(const std::function<void(VulkanContext&)>& work) {
  Impl& impl = *impl_;
  // Taking a ticket goes ahead of the render thread's next slice (impl.lock()), as a move does:
  // with a plain lock the caller had to win the mutex in the instant between two slices, and
  // on a loaded machine it lost for seconds. The turn itself still waits for the end of a
  // round and for every session to be still.
  auto lock = impl.lock();
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
      impl.replaced.wait_for(lock, 2 * Impl::kDeviceRetry,
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
  ServiceStats stats;
  {
    std::lock_guard hold(impl_->published_mutex);
    stats = impl_->published;
  }
  const FrameEncoder::Counters encoded = impl_->frames.counters();
  stats.frames = stats.encode_count = encoded.frames;
  stats.encode_seconds_sum = encoded.encode_seconds_sum;
  return stats;
}

}  // namespace geodesic
