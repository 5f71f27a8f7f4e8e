// How a job the queue started is carried out: rendered here on the daemon's device (JobRunner)
// or handed to a Slurm cluster (SlurmJob, --jobs-backend slurm). The queue sees only this.
#pragma once

#include "jobs/job.h"

namespace geodesic::jobs {

class JobExecution {
 public:
  virtual ~JobExecution() = default;
  // Marks the job cancelled in the store at once; false when it had already ended.
  virtual bool cancel() = 0;
  virtual JobRecord status() const = 0;  // live: progress since the last save too
  virtual bool finished() const = 0;     // its thread is done: the queue may drop it
};

}  // namespace geodesic::jobs
