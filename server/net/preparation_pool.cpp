#include "net/preparation_pool.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "scene/preparation_budget.h"

namespace geodesic::net {
namespace {

constexpr int kWorkerNice = 10;

}  // namespace

PreparationPool::PreparationPool(PreparationOptions options) : options_(options) {
  for (int i = 0; i < options_.threads; ++i) threads_.emplace_back([this] { work(); });
}

PreparationPool::~PreparationPool() { stop(); }

bool PreparationPool::submit(std::function<void()> task) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_ || queue_.size() >= options_.max_queued) return false;
    queue_.push_back(std::move(task));
  }
  wake_.notify_one();
  return true;
}

void PreparationPool::stop() {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    stopping_ = true;
    queue_.clear();
  }
  cancelled_ = true;
  wake_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void PreparationPool::work() {
  // Below the I/O and render threads (Linux nice is per thread): a busy worker never delays a
  // health check or a frame on a machine with few cores. Failure leaves the default.
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), kWorkerNice);
  for (;;) {
    std::function<void()> task;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      task = std::move(queue_.front());
      queue_.pop_front();
    }
    const PreparationScope budget(options_.seconds, &cancelled_);
    task();
  }
}

}  // namespace geodesic::net
