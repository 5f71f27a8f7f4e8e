#include "scene/preparation_budget.h"

#include <cstdio>
#include <string>

#include "scene/scene.h"

namespace geodesic {
namespace {

thread_local PreparationScope* current = nullptr;

}  // namespace

PreparationScope::PreparationScope(double seconds, const std::atomic<bool>* cancelled)
    : deadline_(std::chrono::steady_clock::now() +
                std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                    std::chrono::duration<double>(seconds))),
      seconds_(seconds),
      cancelled_(cancelled),
      outer_(current) {
  current = this;
}

PreparationScope::~PreparationScope() { current = outer_; }

void check_preparation_budget() {
  const PreparationScope* scope = current;
  if (!scope) return;
  if (scope->cancelled_ && scope->cancelled_->load(std::memory_order_relaxed))
    throw SceneError(
        "generators: reading the generators and enumerating their group was cancelled (the "
        "server is stopping)");
  if (std::chrono::steady_clock::now() > scope->deadline_) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", scope->seconds_);
    throw SceneError(
        std::string("generators: reading the generators and enumerating their group exceeded ") +
        seconds + " s (the server's time budget for preparing a scene)");
  }
}

}  // namespace geodesic
