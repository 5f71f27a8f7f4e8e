#include "render/service/session_rota.h"

namespace geodesic {

SessionRota::Sessions::iterator SessionRota::next(Sessions& sessions) {
  if (!out_of_turn_) {  // the urgent session waiting longest
    auto best = sessions.end();
    for (auto it = sessions.begin(); it != sessions.end(); ++it) {
      const RenderSession& s = *it->second;
      if (s.urgent() && (best == sessions.end() || s.reset_time < best->second->reset_time))
        best = it;
    }
    if (best != sessions.end()) {
      out_of_turn_ = true;
      return best;
    }
  }
  out_of_turn_ = false;
  auto it = sessions.upper_bound(last_served_);
  last_served_ = it == sessions.end() ? 0 : it->first;
  return it;
}

}  // namespace geodesic
