#include <algorithm>
#include <cstdio>

#include "render/device/pipeline_cache.h"
#include "render/service/render_service_impl.h"

namespace geodesic {
namespace {

using Clock = std::chrono::steady_clock;

constexpr auto kSlice = std::chrono::duration_cast<Clock::duration>(
    std::chrono::duration<double>(RenderService::kSliceSeconds));

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

}  // namespace

RenderService::Impl::Impl(const std::string& device, std::string dir, ServiceLimits l)
    : device_selector(device),
      ctx(std::make_unique<VulkanContext>(device)),
      scene_dir(std::move(dir)),
      limits(l),
      // Beside the render thread, which lavapipe's own threads keep busy: half the cores.
      frames(std::clamp(int(std::thread::hardware_concurrency()) / 2, 1, 4)) {
  stats.device = ctx->description().name;
  publish();
  thread = std::thread([this] { run(); });
}

RenderService::Impl::~Impl() {
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

void RenderService::Impl::run() {
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
    // A scene being prepared or built beside (a client waits for it, on threads below this
    // one's priority) gets the processor for as long again as a refining slice took: its
    // group enumeration, its renderer and the compilation of its pipeline ahead (warm_up),
    // which lavapipe's threads at full speed would otherwise slow tenfold on a busy machine.
    const auto step_aside =
        beside > 0 || preparing.load() > 0 ? std::min(refining, kSlice) : Clock::duration{};
    // Let waiting callers (moves, new scenes) in between slices.
    publish();
    lock.unlock();
    std::this_thread::sleep_for(step_aside);
    for (int spins = 0; waiting.load() > 0 && spins < 100; ++spins)
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    lock.lock();
  }
}

void RenderService::Impl::fail(SessionId id, const std::string& reason) {
  auto session = sessions.extract(id);
  stats.sessions = int(sessions.size());
  frames.close(*session.mapped()->stream);
  std::fprintf(stderr, "geodesic: session %llu closed: %s\n",
               static_cast<unsigned long long>(id), reason.c_str());
  if (session.mapped()->on_failure) session.mapped()->on_failure(reason);
}

void RenderService::Impl::replace_lost_device() {
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

bool RenderService::Impl::hand_over_background(std::unique_lock<std::mutex>& lock) {
  if (background_queue.empty()) return false;
  for (const auto& [id, s] : sessions)
    if (s->moving) return false;
  granted = background_queue.front();
  background_queue.pop_front();
  background_turn.notify_all();
  background_turn.wait(lock, [this] { return granted == 0; });
  return true;
}

void RenderService::Impl::serve(Session& s) {
  s.serve(frames, stats, recent_samples);
  const double window = seconds_since(window_start);
  if (window > 1.0) {
    stats.samples_per_second = recent_samples / window;
    recent_samples = 0;
    window_start = Clock::now();
  }
}

}  // namespace geodesic
