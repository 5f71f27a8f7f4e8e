// How a job the queue started is carried out: rendered here on the daemon's device (JobRunner)
// or handed to a Slurm cluster (SlurmJob, --jobs-backend slurm). The queue sees only this; the
// record, its saving and cancelling are shared, the work and the files it leaves are each kind's.
#pragma once

#include <atomic>
#include <filesystem>
#include <mutex>
#include <string>

#include "jobs/job.h"
#include "jobs/job_store.h"

namespace geodesic::jobs {

class JobExecution {
 public:
  virtual ~JobExecution() = default;
  JobExecution(const JobExecution&) = delete;
  JobExecution& operator=(const JobExecution&) = delete;

  // Marks the job cancelled in the store at once (a DELETE never waits for the work); the work
  // stops at its next turn. False when the job had already ended.
  bool cancel();
  JobRecord status() const;  // live: progress since the last save too
  bool finished() const { return finished_; }  // the work is done: the queue may drop it

 protected:
  JobExecution(JobStore& store, JobRecord job, std::filesystem::path dir);

  // Persists `state` (a cancel meanwhile wins) and `message` (without the data directory), after
  // removing the files that state leaves no use for (remove_files).
  void save(JobState state, const std::string& message = "");
  virtual void remove_files(JobState state) = 0;
  virtual void wake() {}  // a cancel interrupts the work's wait

  JobStore& store_;
  const std::filesystem::path dir_;
  mutable std::mutex mutex_;  // guards job_
  JobRecord job_;
  std::atomic<bool> cancel_{false}, finished_{false};
};

}  // namespace geodesic::jobs
