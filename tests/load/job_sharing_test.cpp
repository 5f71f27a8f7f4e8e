// A heavy render job beside an interactive session, against a real `geodesic serve`: a thousand
// glass spheres and five hundred point lights at 1920x1080, where one pixel sample costs about
// 0.25 ms on lavapipe and one row of the image half a second. The job's renderer is built
// beside the rendering (not in a device turn) and its passes are cut into slices of about
// RenderService::kSliceSeconds, part of a row when a row is longer (render/service/pass_slicer.h), so
// the session keeps a frame at least every 250 ms and /healthz answers within 100 ms while
// the job is prepared and renders. Before: 17 s without a frame, then 6 s gaps. Time bounds
// are held in the build users run (sanitizer.h).
//
// The daemon gets an empty Mesa shader cache of its own, as on the first run of new shaders:
// lavapipe compiles a pipeline's code at its first dispatch, and the job's took a second on
// the one queue the session shares (gaps of 1.1-1.6 s whenever the cache was cold, the flake
// this test had in CI; none once warm), until RenderService::warm_up compiled it on a device
// of its own.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <random>
#include <thread>

#include <gtest/gtest.h>

#include "../jobs/job_daemon.h"
#include "../net/daemon_fixture.h"
#include "sanitizer.h"
#include "test_constants.h"

namespace geodesic::test {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

json heavy_scene() {
  std::mt19937 random(1);
  auto in = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  json objects = json::array(), lights = json::array();
  for (int i = 0; i < 1000; ++i)
    objects.push_back({{"type", "sphere"}, {"material", "glass"}, {"radius", 0.25},
                       {"center", {in(-4, 4), in(-3, 3), in(-8, -2)}}});
  for (int i = 0; i < 500; ++i)
    lights.push_back({{"type", "point"}, {"intensity", 0.05},
                      {"position", {in(-4, 4), in(-3, 3), in(-8, 0)}}});
  return {{"name", "heavy"},
          {"geometry", "euclidean"},
          {"camera", {{"position", {0, 0, 2}}, {"look_at", {0, 0, 0}}, {"fov_y", 60}}},
          {"materials", {{"glass", {{"transmission", 0.9}, {"ior", 1.5}}}}},
          {"objects", objects},
          {"lights", lights},
          {"render", {{"max_depth", 8}, {"lighting", "physical"}}}};
}

TEST(JobSharing, AHeavyJobLeavesASessionAFrameEveryQuarterSecond) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data", {},
                       {"MESA_SHADER_CACHE_DIR=" + (data.path() / "mesa-shader-cache").string()});
  const JobsApi api(daemon.port());
  WsClient session(daemon.port());
  session.read_until("scene");
  session.send({{"type", "settings"}, {"width", 64}, {"height", 48}});
  session.read_frame();
  for (int i = 0; i < 10; ++i) session.read_frame();  // the session's own passes settled

  const auto posted = Clock::now();
  const int64_t id = api.submit({{"scene", heavy_scene()}, {"width", 1920}, {"height", 1080},
                                 {"spp", 64}, {"formats", {"exr"}}});
  std::atomic<bool> stop{false};
  double slowest_health = 0;
  int health_checks = 0;
  std::thread health([&] {
    while (!stop) {
      const auto start = Clock::now();
      EXPECT_EQ(http_get(daemon.port(), "/healthz").result_int(), 200u);
      slowest_health = std::max(slowest_health, seconds_since(start));
      ++health_checks;
      std::this_thread::sleep_for(50ms);
    }
  });
  // Frames while the job is prepared and starts, then for four seconds of its rendering.
  double longest_gap = 0, running_at = -1;
  int frames = 0;
  auto last = Clock::now();
  while (running_at < 0 || seconds_since(posted) < running_at + 4) {
    session.read_frame(30s);
    longest_gap = std::max(longest_gap, seconds_since(last));
    last = Clock::now();
    ++frames;
    if (running_at < 0 && frames % 10 == 0) {
      const json status = api.get("/api/jobs/" + std::to_string(id)).json;
      if (status["state"] == "running") running_at = seconds_since(posted);
    }
  }
  stop = true;
  health.join();
  const json status = api.get("/api/jobs/" + std::to_string(id)).json;
  EXPECT_EQ(status["state"], "running") << status.dump();
  EXPECT_GT(health_checks, 20);
  if (!kAddressSanitizer) {
    EXPECT_LT(longest_gap, 0.25);
    EXPECT_LT(slowest_health, 0.1);
  }
  std::printf("heavy job (1920x1080, 1000 glass spheres, 500 lights), %.1f s from its POST: "
              "%d session frames, longest gap %.0f ms; %d /healthz, slowest %.0f ms\n",
              seconds_since(posted), frames, longest_gap * 1000, health_checks,
              slowest_health * 1000);
}

}  // namespace
}  // namespace geodesic::test
