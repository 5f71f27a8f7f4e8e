// Runs a command (sbatch, squeue, scancel: the Slurm jobs backend's client tools) and collects
// what it printed. posix_spawnp, no shell: arguments are passed as they are. The child starts
// with an empty signal mask and default dispositions (the daemon blocks SIGINT/SIGTERM in
// every thread and ignores SIGXFSZ; a child must not inherit that).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace geodesic::jobs {

struct CommandResult {
  int exit_code = -1;  // -1: killed (a signal, or the timeout)
  bool timed_out = false;
  std::string out, err;
};

// `argv[0]` is looked up on PATH. `environment` is added to (or overrides) the daemon's own.
// After `timeout_seconds` the command is killed (SIGKILL) and reported timed_out. Throws
// std::runtime_error when it cannot be started at all (e.g. not installed).
CommandResult run_command(const std::vector<std::string>& argv,
                          const std::map<std::string, std::string>& environment = {},
                          double timeout_seconds = 30);

}  // namespace geodesic::jobs
