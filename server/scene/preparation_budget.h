// The time budget and cancellation of expensive scene preparation (reading a generator text,
// group enumeration, Dirichlet domains) on the calling thread. A daemon worker opens a
// PreparationScope around the work; the loops that can run long call check_preparation_budget()
// now and then, which throws SceneError ("generators: reading the generators and enumerating
// their group exceeded N s") once the budget is spent, or when the scope's cancel flag is set
// (the server is stopping). Without a scope (the command line, tests) nothing is checked.
#pragma once

#include <atomic>
#include <chrono>

namespace geodesic {

class PreparationScope {
 public:
  // `cancelled` (may be null) must outlive the scope.
  PreparationScope(double seconds, const std::atomic<bool>* cancelled);
  ~PreparationScope();
  PreparationScope(const PreparationScope&) = delete;
  PreparationScope& operator=(const PreparationScope&) = delete;

 private:
  friend void check_preparation_budget();
  std::chrono::steady_clock::time_point deadline_;
  double seconds_;
  const std::atomic<bool>* cancelled_;
  PreparationScope* outer_;
};

// Throws SceneError when this thread's innermost scope is spent or cancelled.
void check_preparation_budget();

}  // namespace geodesic
