// How render jobs share the device with interactive sessions (RenderService::run_background):
// back to back when no session is open, never while a session is moving (walking keeps its
// frame rate), and one turn per round of the sessions once they are still. "Moving" is a move
// within the last 0.25 s: under AddressSanitizer, whose slowness stretches the test's own
// 50 ms steps past that, the counts are printed, not held (sanitizer.h).
#include <atomic>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "../render/render_fixture.h"
#include "render/service/render_service.h"
#include "sanitizer.h"

namespace geodesic::test {
namespace {

using namespace std::chrono_literals;

TEST(BackgroundTurns, JobsWaitWhileASessionMovesAndShareWhenItIsStill) {
  std::atomic<int> turns{0}, frames{0};  // outlive the service, whose threads count them
  RenderService service("", source_path("scenes/").string());
  std::jthread job([&](std::stop_token stop) {  // joined on every way out of the test
    while (!stop.stop_requested()) {
      service.run_background([&](VulkanContext&) {
        ++turns;
        std::this_thread::sleep_for(5ms);  // a small band of rows
      });
      // A job's own work between turns (reading back, a checkpoint): it asks for the next
      // turn while the render thread is in the middle of a slice.
      std::this_thread::sleep_for(2ms);
    }
  });

  std::this_thread::sleep_for(500ms);
  EXPECT_GT(turns.load(), 20) << "no session: turns back to back";

  const auto id = service.open_session([&](std::shared_ptr<const EncodedFrame>) { ++frames; });
  service.apply_settings(id, {.width = 32, .height = 24});
  // The first frame can wait for the shader compiler (a minute on a cold cache).
  for (int i = 0; i < 2400 && frames.load() < 2; ++i) std::this_thread::sleep_for(100ms);
  ASSERT_GE(frames.load(), 2);
  service.move_camera(id, {.forward = 0.01});
  // A turn handed over just before the move may still run; none after it.
  std::this_thread::sleep_for(50ms);
  service.move_camera(id, {.forward = 0.01});
  const int at_first_move = turns.load();
  const int frames_at_first_move = frames.load();
  for (int i = 0; i < 20; ++i) {  // walking: a move every 50 ms for a second
    std::this_thread::sleep_for(50ms);
    service.move_camera(id, {.yaw = 0.5});
  }
  const int turns_while_moving = turns.load() - at_first_move;
  const int frames_while_moving = frames.load() - frames_at_first_move;
  std::printf("walking for a second: %d job turns, %d frames\n", turns_while_moving,
              frames_while_moving);
  EXPECT_GT(frames_while_moving, 0) << "the moving session got no frames";
  if (!kAddressSanitizer) {
    EXPECT_EQ(turns_while_moving, 0) << "a job had the device while the session moved";
    EXPECT_GT(frames_while_moving, 5) << "the moving session got no frames";
  }

  std::this_thread::sleep_for(1500ms);  // still (settled after 0.25 s): jobs share again
  std::printf("still for 1.5 s: %d job turns, %d frames\n", turns.load() - at_first_move,
              frames.load() - frames_at_first_move - frames_while_moving);
  EXPECT_GT(turns.load(), at_first_move + 5);
}

}  // namespace
}  // namespace geodesic::test
