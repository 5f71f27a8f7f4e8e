// The daemon's render service without the network: sessions, progressive frames, moves,
// settings and bad input.
#include <algorithm>
#include <cmath>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <utility>
#include <vector>

#include "render/service/render_service.h"
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

// Walking far in plain H3: a move that takes the camera more than 2 units from the renderer's
// frame is due a renderer built at the camera; after it, the frames show the moved pose and the
// next small step is not due one.
TEST(RenderService, AWalkOutOfTheFrameGetsARendererCentredOnTheCamera) {
  FrameLog log;  // outlives the service, whose render thread delivers into it until it ends
  RenderService service("", source_path("scenes").string());
  const auto id = service.open_session(log.callback());
  const auto document = nlohmann::ordered_json::parse(R"({"geometry": "hyperbolic",
    "camera": {"position": [0, 0, 2], "look_at": [0, 0, 0]},
    "materials": {"m": {"diffuse": 0.5}},
    "objects": [{"type": "sphere", "material": "m", "center": [0, 0, -4], "radius": 0.5}],
    "lights": [{"type": "point", "position": [0, 2, -3], "intensity": 5}]})");
  service.load_scene_document(id, document);
  service.apply_settings(id, {.width = 32, .height = 32});
  const Mat4 start = parse_scene(document, source_path("scenes")).camera.pose;

  const CameraMotion walk{.forward = 2.5}, step{.forward = 0.1};
  EXPECT_FALSE(service.move_outgrows_frame(id, step));
  ASSERT_TRUE(service.move_outgrows_frame(id, walk));
  PreparedScene centred = service.prepare_move(id, walk);
  service.move_camera(id, walk);
  service.rebase(id, std::move(centred));
  EXPECT_FALSE(service.move_outgrows_frame(id, step));

  const Mat4 walked = apply_motion(GeometryKind::Hyperbolic, start, walk);
  const auto frame = log.wait_for([&](const FrameInfo& f) {
    return f.spp >= 4 && !f.moving && std::abs(f.camera.m[3][3] - walked.m[3][3]) < 1e-6;
  });
  ASSERT_TRUE(frame);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(frame->info.camera.m[i][j], walked.m[i][j], 1e-9);
  EXPECT_EQ(frame->info.non_finite_samples, 0u);
  EXPECT_EQ(frame->info.width, 32);
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

// Frames are encoded off the render thread (render/service/frame_encoder.h): a session's frames still
// come numbered one after another, none after close_session has returned, while the session
// beside it streams on.
TEST(RenderService, FramesComeInOrderAndNoneAfterTheSessionIsClosed) {
  std::mutex mutex;
  std::vector<uint64_t> numbers;  // of the closed session's frames, as they came
  bool closed = false;
  int after_close = 0;
  FrameLog other;  // outlives the service, whose frame workers deliver into it until it ends
  RenderService service("", source_path("scenes").string());
  const auto id = service.open_session([&](std::shared_ptr<const EncodedFrame> frame) {
    std::lock_guard lock(mutex);
    numbers.push_back(frame->info.frame);
    if (closed) ++after_close;
  });
  const auto beside = service.open_session(other.callback());
  service.apply_settings(id, {.width = 48, .height = 48});
  service.apply_settings(beside, {.width = 48, .height = 48});
  const auto streaming = other.wait_for([](const FrameInfo& f) { return f.frame >= 10; });
  ASSERT_TRUE(streaming);
  service.close_session(id);
  {
    std::lock_guard lock(mutex);
    closed = true;
  }
  // The render thread goes round several times more.
  ASSERT_TRUE(other.wait_for([&](const FrameInfo& f) { return f.frame >= streaming->info.frame + 10; }));
  std::lock_guard lock(mutex);
  EXPECT_EQ(after_close, 0);
  ASSERT_GE(numbers.size(), 5u);
  for (size_t i = 0; i < numbers.size(); ++i) EXPECT_EQ(numbers[i], i + 1);
  service.close_session(beside);
}

}  // namespace
}  // namespace geodesic::test
