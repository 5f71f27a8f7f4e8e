// Which session the render thread serves next: round-robin, one slice each, so no session
// starves another; a session someone waits for (RenderSession::urgent: a new view's first
// frame, a new exposure) goes in between, every other slice at most, so its frame waits about
// one slice instead of a round of every session, and the round goes on at half speed or more.
#pragma once

#include <cstdint>
#include <map>
#include <memory>

#include "render/service/render_session.h"

namespace geodesic {

class SessionRota {
 public:
  using Sessions = std::map<uint64_t, std::unique_ptr<RenderSession>>;

  // The session to serve now; end() once a round is over (the next call starts another).
  Sessions::iterator next(Sessions& sessions);
  // Whether the last session returned went out of turn (someone waits for its frame).
  bool out_of_turn() const { return out_of_turn_; }

 private:
  uint64_t last_served_ = 0;  // in the round
  bool out_of_turn_ = false;
};

}  // namespace geodesic
