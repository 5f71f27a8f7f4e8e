#include "jobs/job_queue.h"

#include <algorithm>

namespace geodesic::jobs {
namespace {

std::filesystem::path prepared(const std::filesystem::path& data_dir) {
  std::filesystem::create_directories(data_dir / "jobs");
  return data_dir / "jobs.sqlite3";
}

}  // namespace

JobQueue::JobQueue(RenderService& service, JobOptions options)
    : service_(service), options_(std::move(options)), store_(prepared(options_.data_dir)) {
  // Jobs that were running resume first (from their checkpoints), then the queue in order.
  std::vector<JobRecord> unfinished = store_.list(/*unfinished_only=*/true);
  std::stable_partition(unfinished.begin(), unfinished.end(),
                        [](const JobRecord& job) { return job.state == JobState::Running; });
  for (const JobRecord& job : unfinished) queued_.push_back(job.id);
  scheduler_ = std::thread([this] { schedule(); });
}

JobQueue::~JobQueue() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  scheduler_.join();
  running_.clear();  // each runner stops at its next turn and joins
}

std::filesystem::path JobQueue::job_dir(int64_t id) const {
  return options_.data_dir / "jobs" / std::to_string(id);
}

void JobQueue::schedule() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    std::erase_if(running_, [](const auto& entry) { return entry.second->finished(); });
    while (int(running_.size()) < options_.max_jobs && !queued_.empty()) {
      const int64_t id = queued_.front();
      queued_.pop_front();
      std::optional<JobRecord> job = store_.get(id);
      if (!job || finished(job->state)) continue;
      running_[id] = std::make_unique<JobRunner>(service_, store_, std::move(*job), job_dir(id),
                                                 options_.checkpoint_seconds);
    }
    // Runners do not report their end: a short poll keeps them independent of the queue.
    changed_.wait_for(lock, std::chrono::milliseconds(100));
  }
}

JobRecord JobQueue::submit(const nlohmann::ordered_json& body) {
  const ValidatedJob job = validate_job(body, service_);
  std::lock_guard lock(mutex_);
  if (int(queued_.size()) >= options_.max_queued)
    throw QueueFull("queue: " + std::to_string(queued_.size()) + " jobs waiting, the most this server takes");
  const int64_t id = store_.insert(job.request.to_json());
  queued_.push_back(id);
  changed_.notify_all();
  return *store_.get(id);
}

std::optional<JobRecord> JobQueue::get(int64_t id) const {
  {
    std::lock_guard lock(mutex_);
    if (auto it = running_.find(id); it != running_.end()) return it->second->status();
  }
  return store_.get(id);
}

std::vector<JobRecord> JobQueue::list() const {
  std::vector<JobRecord> jobs = store_.list();
  std::lock_guard lock(mutex_);
  for (JobRecord& job : jobs)
    if (auto it = running_.find(job.id); it != running_.end()) job = it->second->status();
  return jobs;
}

std::optional<JobRecord> JobQueue::cancel(int64_t id) {
  std::lock_guard lock(mutex_);
  if (auto it = running_.find(id); it != running_.end()) {
    JobRunner& runner = *it->second;
    if (!runner.cancel())  // it ended on its own first
      throw AlreadyFinished("state: job " + std::to_string(id) + " is already " +
                            state_name(runner.status().state));
    return runner.status();
  }
  std::optional<JobRecord> job = store_.get(id);
  if (!job) return std::nullopt;
  if (finished(job->state))
    throw AlreadyFinished("state: job " + std::to_string(id) + " is already " + state_name(job->state));
  std::erase(queued_, id);
  job->state = JobState::Cancelled;
  store_.update(*job);
  std::filesystem::remove_all(job_dir(id));
  return job;
}

std::filesystem::path JobQueue::result_file(int64_t id, const std::string& format) const {
  return job_dir(id) / ("result." + format);
}

}  // namespace geodesic::jobs
