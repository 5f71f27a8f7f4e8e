// Sessions against careless and silent clients: a move too large for the model is refused with
// its field named and the pose stays finite; a silent session gives up its slot to a new client
// when the server is full, a talking one does not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <thread>

#include "daemon_fixture.h"

namespace geodesic::test {
namespace {

using nlohmann::json;

bool finite_camera(const json& frame) {
  if (!frame["camera"].is_array() || frame["camera"].size() != 16) return false;
  for (const json& v : frame["camera"])
    if (!v.is_number() || !std::isfinite(v.get<double>())) return false;
  return true;
}

TEST(SessionLimits, HugeMovesAreRefusedAndThePoseStaysFinite) {
  Daemon daemon;
  WsClient client(daemon.port());
  client.read_scene();
  client.send({{"type", "settings"}, {"width", 64}, {"height", 48}});
  for (const auto& [field, value] : {std::pair{"forward", 1e308}, {"yaw", 1e308}, {"up", -11.0},
                                     {"roll", 361.0}}) {
    client.send({{"type", "move"}, {field, value}});
    const json error = client.read_until("error");
    EXPECT_EQ(error["field"], field) << error;
  }
  client.send({{"type", "move"}, {"forward", 0.1}, {"yaw", 30}});
  for (int i = 0; i < 3; ++i) {
    const WsClient::Frame frame = client.read_frame();
    EXPECT_TRUE(finite_camera(frame.info)) << frame.info;
  }
}

TEST(SessionLimits, ASilentSessionGivesUpItsSlotWhenTheServerIsFull) {
  DaemonOptions options;
  options.limits.max_sessions = 1;
  options.idle_eviction = std::chrono::milliseconds(2000);
  Daemon daemon(options);
  WsClient silent(daemon.port());
  silent.read_until("hello");
  {
    WsClient early(daemon.port());  // the silent one has not been silent long enough
    EXPECT_EQ(early.read_until_close(10s), 1013) << "the early client got the slot";
  }
  std::printf("early client refused\n");
  std::this_thread::sleep_for(std::chrono::milliseconds(2300));
  const auto start = std::chrono::steady_clock::now();
  WsClient newcomer(daemon.port());
  EXPECT_EQ(newcomer.read_until("hello")["type"], "hello");
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(waited, 1.0);
  std::printf("newcomer in after %.3f s\n", waited);
  EXPECT_EQ(silent.read_until_close(10s), 4000);
  newcomer.read_frame();  // the newcomer renders
}

}  // namespace
}  // namespace geodesic::test
