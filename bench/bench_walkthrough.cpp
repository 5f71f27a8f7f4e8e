// The interactive figures of the daemon's render service (without the network, whose loopback
// cost is negligible next to these): for a scene at 640x480 on the current device,
//   - latency from a camera move to the first frame of the new view,
//   - frames/s while the camera keeps moving (a move every 50 ms, as a held key sends),
//   - time from the last move to a clean image (estimated error below 5 %, then 2 %), the
//     moves having come back to about the scene's own view,
//   - JPEG encode time per frame.
//   geodesic_bench_walkthrough [SCENE-NAME] [--device SEL] [--width W --height H] [--save F.jpg]
// --save writes the last still frame, to look at what the error figures are of.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <fstream>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "render/service/render_service.h"

using namespace geodesic;
using Clock = std::chrono::steady_clock;

namespace {

struct Frames {
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::pair<Clock::time_point, FrameInfo>> log;
  std::shared_ptr<const EncodedFrame> last;

  RenderService::FrameCallback callback() {
    return [this](std::shared_ptr<const EncodedFrame> f) {
      std::lock_guard lock(mutex);
      log.emplace_back(Clock::now(), f->info);
      last = f;
      changed.notify_all();
    };
  }

  // Time of the first frame after `since` that satisfies ok (or none within the timeout).
  template <typename Ok>
  std::optional<std::pair<Clock::time_point, FrameInfo>> wait(Clock::time_point since, Ok ok,
                                                              double timeout = 60) {
    std::unique_lock lock(mutex);
    std::optional<std::pair<Clock::time_point, FrameInfo>> found;
    changed.wait_for(lock, std::chrono::duration<double>(timeout), [&] {
      for (const auto& entry : log)
        if (entry.first > since && ok(entry.second)) {
          found = entry;
          return true;
        }
      return false;
    });
    return found;
  }
};

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

}  // namespace

int main(int argc, char** argv) try {
  std::string scene = "cornell-box", device, save;
  int width = 640, height = 480;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--device" && i + 1 < argc) device = argv[++i];
    else if (a == "--width" && i + 1 < argc) width = std::stoi(argv[++i]);
    else if (a == "--height" && i + 1 < argc) height = std::stoi(argv[++i]);
    else if (a == "--save" && i + 1 < argc) save = argv[++i];
    else scene = a;
  }
  RenderService service(device, std::string(GEODESIC_SOURCE_DIR) + "/scenes");
  Frames frames;
  const auto id = service.open_session(frames.callback());
  service.load_scene(id, scene);
  service.apply_settings(id, {.width = width, .height = height});
  frames.wait(Clock::now(), [](const FrameInfo& f) { return f.spp >= 2; });

  // Latency: move, then the first frame showing the new view.
  std::vector<double> latencies;
  for (int i = 0; i < 10; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    const auto moved = Clock::now();
    service.move_camera(id, {.forward = (i % 2 ? -0.02 : 0.02), .yaw = (i % 2 ? 1.0 : -1.0)});
    if (auto f = frames.wait(moved, [](const FrameInfo& f) { return f.moving; }))
      latencies.push_back(ms(f->first - moved));
  }
  std::sort(latencies.begin(), latencies.end());

  // Frames per second while moving: a move every 50 ms for 3 s, 30 out and 30 back, so that the
  // still view is about the scene's own (Seifert-Weber's walk ended inside an object, and the
  // still phase timed a black image).
  const auto walk_start = Clock::now();
  for (int i = 0; i < 60; ++i) {
    const double way = i < 30 ? 1.0 : -1.0;
    service.move_camera(id, {.forward = 0.01 * way, .yaw = 0.5 * way});
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const auto walk_end = Clock::now();
  // The walk's frame widths: the median, the range, and how often it changed (the session sizes
  // a moving frame from the measured cost, which wavers).
  std::vector<int> widths;
  size_t resizes = 0;
  {
    std::lock_guard lock(frames.mutex);
    for (const auto& [t, f] : frames.log)
      if (t > walk_start && t <= walk_end) {
        if (!widths.empty() && f.width != widths.back()) ++resizes;
        widths.push_back(f.width);
      }
  }
  const size_t walk_frames = widths.size();
  std::sort(widths.begin(), widths.end());
  if (widths.empty()) widths.push_back(0);

  // Time to a clean image once still.
  const auto still = Clock::now();
  auto at5 = frames.wait(still, [](const FrameInfo& f) { return !f.moving && f.error > 0 && f.error < 0.05; });
  std::optional<std::pair<Clock::time_point, FrameInfo>> at2;
  if (at5) at2 = frames.wait(still, [](const FrameInfo& f) { return !f.moving && f.error > 0 && f.error < 0.02; });
  const ServiceStats stats = service.stats();

  std::printf("scene %s at %dx%d on %s\n", scene.c_str(), width, height, stats.device.c_str());
  if (!latencies.empty())
    std::printf("move -> first frame:      median %.0f ms, worst %.0f ms (%zu moves)\n",
                latencies[latencies.size() / 2], latencies.back(), latencies.size());
  std::printf("frames/s while moving:    %.1f (median %d px wide; %d-%d px, %zu size changes)\n",
              walk_frames / std::chrono::duration<double>(walk_end - walk_start).count(),
              widths[widths.size() / 2], widths.front(), widths.back(), resizes);
  // Unreached within the wait: where the still image stood when it ended.
  std::optional<std::pair<Clock::time_point, FrameInfo>> last;
  {
    std::lock_guard lock(frames.mutex);
    if (!frames.log.empty() && !frames.log.back().second.moving) last = frames.log.back();
  }
  for (const auto& [bound, at] : {std::pair{5, at5}, std::pair{2, at2}}) {
    if (at)
      std::printf("still -> error < %d%%:      %.2f s (%u spp)\n", bound, ms(at->first - still) / 1e3,
                  at->second.spp);
    else if (last)
      std::printf("still -> error < %d%%:      not in %.0f s (%.2f %% at %u spp)\n", bound,
                  ms(last->first - still) / 1e3, 100 * last->second.error, last->second.spp);
  }
  std::printf("JPEG encode per frame:    %.2f ms (%llu frames)\n",
              1e3 * stats.encode_seconds_sum / std::max<uint64_t>(1, stats.encode_count),
              static_cast<unsigned long long>(stats.encode_count));
  if (!save.empty()) {
    std::lock_guard lock(frames.mutex);
    if (frames.last) {
      std::ofstream out(save, std::ios::binary);
      out.write(reinterpret_cast<const char*>(frames.last->jpeg.data()), std::streamsize(frames.last->jpeg.size()));
      if (!out) std::fprintf(stderr, "cannot write %s\n", save.c_str());
    }
  }
  service.close_session(id);
  return 0;
} catch (const std::exception& e) {  // an unknown scene name, a device that will not start
  std::fprintf(stderr, "geodesic_bench_walkthrough: %s\n", e.what());
  return 1;
}
