// Renders one job to its stop condition on a thread of its own, taking the device only in the
// turns RenderService::run_background hands out (interactive sessions first). At the end of a
// pass, at most every checkpoint_seconds, it checkpoints the accumulation (checkpoint.h) and
// saves its progress in the store; a resumed job starts from that checkpoint with the sample
// count, and so the random streams, going on. When done it writes the results atomically and
// reads them back. A lost device makes it start over from its checkpoint on the service's new
// one (a few times); any other error fails the job with the reason, and its files go.
#pragma once

#include <atomic>
#include <filesystem>
#include <mutex>
#include <thread>

#include "jobs/job_execution.h"
#include "jobs/job_store.h"
#include "render/service/render_service.h"

namespace geodesic::jobs {

class JobRunner : public JobExecution {
 public:
  // `job` is queued, or running when the daemon stopped: its folder `dir` may hold a checkpoint.
  JobRunner(RenderService& service, JobStore& store, JobRecord job, std::filesystem::path dir,
            double checkpoint_seconds);
  // A shutdown: finishes the pass in progress, checkpoints it, and leaves the job running in the
  // store, to resume on the next start.
  ~JobRunner() override;
  // A cancel (JobExecution::cancel) frees the device and deletes the checkpoint at the runner's
  // next device turn.

 private:
  void run();
  void render();
  // A failed job's results may be half written: its folder goes; an ended job's checkpoint goes.
  void remove_files(JobState state) override;

  RenderService& service_;
  const double checkpoint_seconds_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace geodesic::jobs
