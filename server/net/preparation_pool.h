// The daemon's scene preparation off the I/O threads: generator enumeration, Dirichlet domains,
// scene documents and mesh loading run on a few worker threads, each task under a time budget
// (scene/preparation_budget.h), so that a hostile generator text costs one worker for at most
// that long while /healthz, frames and every other request carry on. The queue is bounded:
// submit() refuses work beyond it (the client is told the server is busy).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace geodesic::net {

struct PreparationOptions {
  int threads = 2;
  std::size_t max_queued = 16;  // waiting tasks beyond the running ones
  double seconds = 10;          // budget of one task
};

class PreparationPool {
 public:
  explicit PreparationPool(PreparationOptions options);
  ~PreparationPool();  // stop()
  PreparationPool(const PreparationPool&) = delete;
  PreparationPool& operator=(const PreparationPool&) = delete;

  // Queues `task`; false (and nothing queued) when the queue is full or the pool is stopping.
  // The task must catch its own exceptions; a spent budget throws SceneError inside it.
  bool submit(std::function<void()> task);
  // Cancels the running tasks (their next budget check throws), drops the queued ones and joins
  // the workers. Idempotent.
  void stop();

  double seconds() const { return options_.seconds; }

 private:
  void work();

  PreparationOptions options_;
  std::atomic<bool> cancelled_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> queue_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace geodesic::net
