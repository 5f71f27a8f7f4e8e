// A render job handed to a Slurm cluster (`geodesic serve --jobs-backend slurm`) instead of the
// daemon's own device: deploy/slurm/submit.sh splits its samples into an sbatch array of parts
// (`geodesic render --samples-from K --samples N --accumulation`) and a merge step that runs when
// every part succeeded (`geodesic merge`, one image per format asked for). Status and results go
// through the same store and API as a local job:
//  - queued until submitted; running while either Slurm job is pending or running (progress:
//    parts whose accumulation exists); done when the merge wrote every result; failed, with the
//    failing step's last message, when a part or the merge did not;
//  - DELETE scancels both; a daemon that stops leaves the cluster working and picks the job up
//    again on its next start (the Slurm job ids are kept in the job's folder, slurm.json).
// The job folder (under --data) and the geodesic executable must be at the same paths on every
// node (shared storage), as for submit.sh. The stop condition must be a sample count (spp): a
// time or an error target cannot be split into parts beforehand.
#pragma once

#include <atomic>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>

#include "jobs/job_execution.h"
#include "jobs/job_store.h"
#include "render/service/render_service.h"

namespace geodesic::jobs {

struct SlurmOptions {
  std::filesystem::path scripts;    // deploy/slurm: submit.sh, render-part.sbatch, merge.sbatch
  std::filesystem::path binary;     // the geodesic executable the nodes run
  std::filesystem::path scene_dir;  // bundled scenes; inline documents' files resolve there too
  int parts = 4;                    // at most this many parts (a divisor of the job's spp)
  double poll_seconds = 2;          // squeue at most this often per job
};

// The number of parts a job of `spp` samples is split into: the largest divisor of spp that is
// at most `most` (every part renders the same count).
int slurm_parts(uint32_t spp, int most);

class SlurmJob : public JobExecution {
 public:
  SlurmJob(RenderService& service, JobStore& store, JobRecord job, std::filesystem::path dir,
           SlurmOptions options);
  // Stops watching; the job stays running in the store and on the cluster.
  ~SlurmJob() override;

 private:
  void run();
  void submit();
  bool active();   // either Slurm job still pending or running
  void progress();
  void collect();  // after both left the queue: done with the results, or failed with why
  // A failed or cancelled job's folder goes (parts, logs, results half merged).
  void remove_files(JobState state) override;
  void wake() override { wake_.notify_all(); }

  RenderService& service_;
  const SlurmOptions options_;
  std::string parts_job_, merge_job_;  // Slurm job ids
  int parts_ = 0;
  uint32_t samples_per_part_ = 0;
  double submitted_ = 0;  // Unix time
  std::condition_variable wake_;  // with mutex_: a stop or a cancel ends the wait between polls
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace geodesic::jobs
