#include "jobs/job_queue.h"

#include <algorithm>
#include <charconv>
#include <string>

namespace geodesic::jobs {
namespace {

std::filesystem::path prepared(const std::filesystem::path& data_dir) {
  std::filesystem::create_directories(data_dir / "jobs");
  return data_dir / "jobs.sqlite3";
}

// The largest id among the job directories (0 when none).
int64_t largest_job_dir(const std::filesystem::path& jobs_dir) {
  int64_t largest = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(jobs_dir, ec)) {
    const std::string name = entry.path().filename().string();
    int64_t id = 0;
    const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), id);
    if (error == std::errc() && end == name.data() + name.size()) largest = std::max(largest, id);
  }
  return largest;
}

}  // namespace

JobQueue::JobQueue(RenderService& service, JobOptions options)
    : service_(service), options_(std::move(options)), store_(prepared(options_.data_dir)) {
  store_.reserve_ids_above(largest_job_dir(options_.data_dir / "jobs"));
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
  bool retained = false;
  while (!stopping_) {
    const std::size_t before = running_.size();
    std::erase_if(running_, [](const auto& entry) { return entry.second->finished(); });
    if (!retained || running_.size() != before) retain();
    retained = true;
    const bool local = options_.backend == JobOptions::Backend::Local;
    while ((!local || int(running_.size()) < options_.max_jobs) && !queued_.empty()) {
      const int64_t id = queued_.front();
      queued_.pop_front();
      std::optional<JobRecord> job = store_.get(id);
      if (!job || finished(job->state)) continue;
      if (local)
        running_[id] = std::make_unique<JobRunner>(service_, store_, std::move(*job), job_dir(id),
                                                   options_.checkpoint_seconds);
      else
        running_[id] = std::make_unique<SlurmJob>(service_, store_, std::move(*job), job_dir(id),
                                                  options_.slurm);
    }
    // Runners do not report their end: a short poll keeps them independent of the queue.
    changed_.wait_for(lock, std::chrono::milliseconds(100));
  }
}

JobRecord JobQueue::submit(const nlohmann::ordered_json& body) {
  const ValidatedJob job = validate_job(body, service_);
  if (options_.backend == JobOptions::Backend::Slurm && !job.request.stop.spp)
    throw RequestError(std::string(job.request.stop.seconds ? "seconds" : "target_error") +
                       ": this server renders jobs on a Slurm cluster, split into parts of equal "
                       "sample counts: give spp");
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

std::vector<JobRecord> JobQueue::list(int64_t after, int limit) const {
  std::vector<JobRecord> jobs = store_.page(after, limit);
  std::lock_guard lock(mutex_);
  for (JobRecord& job : jobs)
    if (auto it = running_.find(job.id); it != running_.end()) job = it->second->status();
  return jobs;
}

std::optional<JobRecord> JobQueue::cancel(int64_t id) {
  std::lock_guard lock(mutex_);
  if (auto it = running_.find(id); it != running_.end()) {
    JobExecution& runner = *it->second;
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

bool JobQueue::remove(int64_t id) {
  std::lock_guard lock(mutex_);
  if (auto it = running_.find(id); it != running_.end()) {
    const JobState state = it->second->status().state;
    if (!finished(state))
      throw AlreadyFinished("state: job " + std::to_string(id) + " is " + state_name(state) +
                            "; cancel it first (DELETE without remove)");
    running_.erase(it);  // a cancelled runner: joined, it stops at its next turn
  }
  std::optional<JobRecord> job = store_.get(id);
  if (!job) return false;
  if (!finished(job->state))
    throw AlreadyFinished("state: job " + std::to_string(id) + " is " + state_name(job->state) +
                          "; cancel it first (DELETE without remove)");
  store_.remove(id);
  std::error_code ignored;
  std::filesystem::remove_all(job_dir(id), ignored);
  return true;
}

void JobQueue::retain() {
  if (options_.keep_jobs <= 0) return;
  const std::vector<int64_t> ids = store_.finished_ids();  // newest first
  for (std::size_t i = std::size_t(options_.keep_jobs); i < ids.size(); ++i) {
    if (running_.contains(ids[i])) continue;  // its runner still saves the end
    store_.remove(ids[i]);
    std::error_code ignored;
    std::filesystem::remove_all(job_dir(ids[i]), ignored);
  }
}

std::filesystem::path JobQueue::result_file(int64_t id, const std::string& format) const {
  return job_dir(id) / ("result." + format);
}

}  // namespace geodesic::jobs
