// The render thread's rota (render/service/session_rota.h): round-robin, and a session someone waits
// for in between, every other slice at most.
#include <gtest/gtest.h>

#include <chrono>
#include <vector>

#include "render/service/session_rota.h"

namespace geodesic::test {
namespace {

// Serves `count` slices, as the render thread does: end() closes a round; an urgent session
// served has its frame out (it is no longer urgent).
std::vector<uint64_t> serve(SessionRota& rota, SessionRota::Sessions& sessions, int count) {
  std::vector<uint64_t> order;
  while (int(order.size()) < count) {
    auto it = rota.next(sessions);
    if (it == sessions.end()) {
      order.push_back(0);
      continue;
    }
    order.push_back(it->first);
    it->second->first_frame_due = false;
  }
  return order;
}

SessionRota::Sessions still_sessions(int count) {
  SessionRota::Sessions sessions;
  for (int id = 1; id <= count; ++id) {
    sessions[id] = std::make_unique<RenderSession>();
    sessions[id]->first_frame_due = false;
  }
  return sessions;
}

TEST(SessionRota, StillSessionsTakeTurns) {
  auto sessions = still_sessions(3);
  SessionRota rota;
  EXPECT_EQ(serve(rota, sessions, 8), (std::vector<uint64_t>{1, 2, 3, 0, 1, 2, 3, 0}));
}

TEST(SessionRota, NewViewsGoInBetweenOldestFirstAndTheRoundGoesOn) {
  auto sessions = still_sessions(5);
  SessionRota rota;
  EXPECT_EQ(serve(rota, sessions, 2), (std::vector<uint64_t>{1, 2}));
  const auto now = RenderSession::Clock::now();
  sessions[5]->first_frame_due = true;  // moved first
  sessions[5]->reset_time = now - std::chrono::milliseconds(2);
  sessions[1]->first_frame_due = true;  // then
  sessions[1]->reset_time = now - std::chrono::milliseconds(1);
  sessions[4]->reexpose = true;  // a new exposure: at once too
  sessions[4]->reset_time = now - std::chrono::seconds(9);
  EXPECT_EQ(serve(rota, sessions, 1), std::vector<uint64_t>{4});
  sessions[4]->reexpose = false;  // its frame re-encoded (RenderSession::serve clears it)
  EXPECT_EQ(serve(rota, sessions, 7), (std::vector<uint64_t>{3, 5, 4, 1, 5, 0, 1}));
}

// Sessions urgent again after every frame (walking without pause) still leave the others half
// the slices: nobody starves.
TEST(SessionRota, UrgentSessionsTakeEveryOtherSliceAtMost) {
  auto sessions = still_sessions(4);
  SessionRota rota;
  std::vector<uint64_t> order;
  for (int slice = 0; slice < 12; ++slice) {
    sessions[2]->first_frame_due = true;
    sessions[2]->reset_time = RenderSession::Clock::now();
    auto it = rota.next(sessions);
    order.push_back(it == sessions.end() ? 0 : it->first);
  }
  EXPECT_EQ(order, (std::vector<uint64_t>{2, 1, 2, 2, 2, 3, 2, 4, 2, 0, 2, 1}));
}

}  // namespace
}  // namespace geodesic::test
