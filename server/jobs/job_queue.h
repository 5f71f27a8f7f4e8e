// The render jobs of one daemon: accepts them into the store, runs up to max_jobs at once in
// submission order (jobs that were running when the daemon last stopped first, from their
// checkpoints), cancels, and finds their results. Files live under the data directory:
// jobs.sqlite3 (the table) and jobs/<id>/ (checkpoint.bin, result.<format>). Thread-safe.
// With the Slurm backend a started job is handed to the cluster (slurm_job.h) instead.
#pragma once

#include <condition_variable>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "jobs/job_runner.h"
#include "jobs/slurm_job.h"
#include "jobs/job_store.h"

namespace geodesic::jobs {

struct JobOptions {
  std::filesystem::path data_dir;
  int max_jobs = 1;           // rendering at once
  int max_queued = 100;       // waiting; more is QueueFull (429)
  double checkpoint_seconds = 10;
  int keep_jobs = 0;          // > 0: finished jobs beyond the newest this many are removed
  // Where jobs render: on this daemon's device (max_jobs at once), or on a Slurm cluster (every
  // queued job is submitted at once: the cluster's scheduler queues them).
  enum class Backend { Local, Slurm } backend = Backend::Local;
  SlurmOptions slurm;
};

class QueueFull : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Cancelling a job that has already ended, or removing one that has not (409).
class AlreadyFinished : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

class JobQueue {
 public:
  // Creates the data directory, opens the store and resumes its unfinished jobs. `service`
  // must outlive the queue. Throws std::runtime_error (e.g. an unwritable directory).
  JobQueue(RenderService& service, JobOptions options);
  ~JobQueue();  // running jobs stop where they are, to resume on the next start
  JobQueue(const JobQueue&) = delete;
  JobQueue& operator=(const JobQueue&) = delete;

  // Validates (RequestError), checks the queue (QueueFull) and stores a new job.
  JobRecord submit(const nlohmann::ordered_json& body);
  std::optional<JobRecord> get(int64_t id) const;  // live progress while it runs
  // In id order: at most `limit` jobs with ids above `after` (limit 0: all of them).
  std::vector<JobRecord> list(int64_t after = 0, int limit = 0) const;
  // Removes a finished job and its files; false when unknown; throws AlreadyFinished (sic: the
  // 409) while it is queued or running.
  bool remove(int64_t id);
  // The job as it ended (cancelled); nullopt when unknown; throws AlreadyFinished.
  std::optional<JobRecord> cancel(int64_t id);
  std::filesystem::path result_file(int64_t id, const std::string& format) const;

 private:
  void schedule();  // the scheduler thread: reaps ended runners, starts queued jobs
  std::filesystem::path job_dir(int64_t id) const;
  void retain();  // --keep-jobs: removes the oldest finished jobs beyond the count

  RenderService& service_;
  const JobOptions options_;
  JobStore store_;
  mutable std::mutex mutex_;  // guards the members below
  std::condition_variable changed_;
  std::deque<int64_t> queued_;  // in start order
  std::map<int64_t, std::unique_ptr<JobExecution>> running_;
  bool stopping_ = false;
  std::thread scheduler_;
};

}  // namespace geodesic::jobs
