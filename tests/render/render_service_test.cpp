// The daemon's render service without the network: sessions, progressive frames, moves,
// settings and bad input.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <utility>
#include <vector>

#include "render/render_service.h"
#include "render_fixture.h"

namespace geodesic::test {
namespace {

// Collects a session's frames; waits for the next one that satisfies a condition.
class FrameLog {
 public:
  RenderService::FrameCallback callback() {
    return [this](std::shared_ptr<const EncodedFrame> frame) {
      std::lock_guard lock(mutex_);
      last_ = std::move(frame);
      changed_.notify_all();
    };
  }

  template <typename Predicate>
  std::shared_ptr<const EncodedFrame> wait_for(Predicate ok, double seconds = 20) {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, std::chrono::duration<double>(seconds),
                      [&] { return last_ && ok(last_->info); });
    return last_ && ok(last_->info) ? last_ : nullptr;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::shared_ptr<const EncodedFrame> last_;
};

TEST(RenderService, StreamsRefiningFramesAndRestartsOnAMove) {
  FrameLog log;  // outlives the service, whose render thread delivers into it until it ends
  RenderService service("", source_path("scenes").string());
  const auto id = service.open_session(log.callback());
  service.apply_settings(id, {.width = 64, .height = 48});

  auto first = log.wait_for([](const FrameInfo& f) { return f.width == 64 && f.spp >= 2; });
  ASSERT_TRUE(first);
  EXPECT_EQ(first->jpeg.at(0), 0xFF);  // JPEG SOI marker
  EXPECT_EQ(first->jpeg.at(1), 0xD8);
  const double early_error = first->info.error;
  auto later = log.wait_for([&](const FrameInfo& f) { return f.spp >= 8 * first->info.spp; });
  ASSERT_TRUE(later);
  EXPECT_LT(later->info.error, early_error);

  service.move_camera(id, {.forward = 0.2});
  auto moved = log.wait_for([](const FrameInfo& f) { return f.moving; });
  ASSERT_TRUE(moved);
  EXPECT_EQ(moved->info.width, 32);  // reduced resolution while moving
  EXPECT_LT(moved->info.spp, later->info.spp);
  EXPECT_NE(moved->info.camera.m[2][3], later->info.camera.m[2][3]);
  auto settled = log.wait_for([](const FrameInfo& f) { return !f.moving && f.width == 64; });
  ASSERT_TRUE(settled);
  EXPECT_GT(service.stats().frames, 3u);
}

TEST(RenderService, BadInputNamesTheFieldAndKeepsTheScene) {
  FrameLog log;  // outlives the service, whose render thread delivers into it until it ends
  RenderService service("", source_path("scenes").string());
  const auto id = service.open_session(log.callback());
  EXPECT_THROW(service.load_scene(id, "no-such-scene"), SceneError);
  try {
    service.load_scene_document(id, nlohmann::ordered_json::parse(R"({"geometry": "flat"})"));
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("geometry: unknown geometry"), std::string::npos);
  }
  EXPECT_THROW(service.apply_settings(id, {.width = 4}), std::invalid_argument);
  const SceneInfo info = service.apply_settings(id, {.width = 40, .height = 30});
  EXPECT_EQ(info.name, "cornell-box");  // still the old scene
  ASSERT_TRUE(log.wait_for([](const FrameInfo& f) { return f.width == 40 && f.spp > 0; }));
  const SceneInfo torus = service.load_scene(id, "torus-cornell");
  EXPECT_EQ(torus.manifold, "torus");
}

TEST(RenderService, SessionsShareTheDeviceFairly) {
  FrameLog a, b;  // outlive the service (its render thread delivers into them)
  RenderService service("", source_path("scenes").string(), {.max_sessions = 2});
  const auto first = service.open_session(a.callback());
  const auto second = service.open_session(b.callback());
  EXPECT_THROW(service.open_session(FrameLog().callback()), std::runtime_error);
  service.apply_settings(first, {.width = 48, .height = 48});
  service.apply_settings(second, {.width = 48, .height = 48});
  ASSERT_TRUE(a.wait_for([](const FrameInfo& f) { return f.frame >= 10; }));
  ASSERT_TRUE(b.wait_for([](const FrameInfo& f) { return f.frame >= 10; }));
  service.close_session(first);
  EXPECT_EQ(service.stats().sessions, 1);
  service.close_session(second);
}

// A moved session's first frame goes out of turn: beside seven busy sessions it waits for at
// most one other session's slice, not a round of seven.
TEST(RenderService, ANewViewsFirstFrameDoesNotWaitForTheRound) {
  constexpr int kSessions = 8;
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::pair<int, bool>> frames;  // (session, moving) in the order they came
  RenderService service("", source_path("scenes").string(), {.max_sessions = kSessions});
  std::vector<RenderService::SessionId> ids;
  for (int i = 0; i < kSessions; ++i) {
    ids.push_back(service.open_session([&, i](std::shared_ptr<const EncodedFrame> frame) {
      std::lock_guard lock(mutex);
      frames.emplace_back(i, frame->info.moving);
      changed.notify_all();
    }));
    service.apply_settings(ids.back(), {.width = 32, .height = 32});
  }
  auto wait = [&](auto ok) {
    std::unique_lock lock(mutex);
    return changed.wait_for(lock, std::chrono::seconds(60), [&] { return ok(frames); });
  };
  // Every session streams (each pass one slice at this size).
  ASSERT_TRUE(wait([&](const auto& log) {
    for (int i = 0; i < kSessions; ++i)
      if (std::count(log.begin(), log.end(), std::pair{i, false}) < 3) return false;
    return true;
  }));
  for (int move = 0; move < 6; ++move) {
    const int mover = move % kSessions;
    size_t before = 0;
    {
      std::lock_guard lock(mutex);
      before = frames.size();
    }
    // move_camera waits for the slice under way: what follows it is rendered after the move.
    service.move_camera(ids[mover], {.yaw = move % 2 ? 2.0 : -2.0});
    const auto moved = [&](const auto& log) {
      return std::find(log.cbegin() + before, log.cend(), std::pair{mover, true});
    };
    ASSERT_TRUE(wait([&](const auto& log) { return moved(log) != log.cend(); })) << "move " << move;
    std::lock_guard lock(mutex);
    const auto others = std::count_if(frames.cbegin() + before, moved(frames),
                                      [&](const auto& frame) { return frame.first != mover; });
    EXPECT_LE(others, 2) << "move " << move << ": frames of other sessions before the moved one's";
  }
  for (const auto id : ids) service.close_session(id);
}

}  // namespace
}  // namespace geodesic::test
