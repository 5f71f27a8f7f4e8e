#include "jobs/job_execution.h"

namespace geodesic::jobs {

JobExecution::JobExecution(JobStore& store, JobRecord job, std::filesystem::path dir)
    : store_(store), dir_(std::move(dir)), job_(std::move(job)) {}

bool JobExecution::cancel() {
  {
    std::lock_guard lock(mutex_);
    if (jobs::finished(job_.state)) return false;
    job_.state = JobState::Cancelled;
    cancel_ = true;
  }
  wake();
  save(JobState::Cancelled);
  return true;
}

JobRecord JobExecution::status() const {
  std::lock_guard lock(mutex_);
  return job_;
}

void JobExecution::save(JobState state, const std::string& message) {
  JobRecord copy;
  {
    std::lock_guard lock(mutex_);
    if (job_.state == JobState::Cancelled) state = JobState::Cancelled;  // a cancel wins
    job_.state = state;
    job_.message = without_data_dir(message, dir_);
    copy = job_;
  }
  remove_files(state);
  store_.update(copy);
}

}  // namespace geodesic::jobs
