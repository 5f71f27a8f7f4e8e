// `geodesic serve`: the render daemon. HTTP and WebSocket on one port (docs/protocol.md) and
// render jobs kept in a data directory, until SIGINT or SIGTERM, which close the sessions
// gracefully (running jobs resume from their checkpoints on the next start, as after a kill).
// Every option can also come from the environment (GEODESIC_HOST for --host, and so on:
// containers are configured that way); a flag wins over its variable.
#include <cctype>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <pthread.h>

#include "jobs/job_queue.h"
#include "net/auth.h"
#include "net/server.h"
#include "render/service/render_service.h"

namespace geodesic {
namespace {

struct ServeOptions {
  net::ServerOptions server;
  jobs::JobOptions jobs;
  ServiceLimits limits;
  std::string device;
};

constexpr const char* kFlags[] = {"--host", "--port", "--device", "--web", "--data", "--token",
                                  "--max-jobs", "--max-queue", "--checkpoint-seconds",
                                  "--max-sessions", "--max-depth", "--prepare-seconds", "--keep-jobs",
                                  "--jobs-backend", "--slurm-parts", "--slurm-scripts"};

// $XDG_DATA_HOME/geodesic, else ~/.local/share/geodesic (the XDG base directory default).
std::filesystem::path default_data_dir() {
  if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "geodesic";
  const char* home = std::getenv("HOME");
  if (!home || !*home) throw std::invalid_argument("--data: no HOME to put the default under; give --data DIR");
  return std::filesystem::path(home) / ".local" / "share" / "geodesic";
}

// "--max-jobs" -> "GEODESIC_MAX_JOBS"
std::string env_name(const std::string& flag) {
  std::string name = "GEODESIC_";
  for (char c : flag.substr(2)) name += c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

long integer(const std::string& flag, const std::string& v, long lo, long hi) {
  size_t used = 0;
  long value = lo - 1;
  try { value = std::stol(v, &used); } catch (const std::exception&) { used = 0; }
  if (used != v.size() || value < lo || value > hi)
    throw std::invalid_argument(flag + ": must be an integer in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "], not \"" + v + "\"");
  return value;
}

void apply(ServeOptions& options, const std::string& flag, const std::string& value) {
  if (flag == "--host") options.server.host = value;
  else if (flag == "--port") options.server.port = uint16_t(integer(flag, value, 0, 65535));
  else if (flag == "--device") options.device = value;
  else if (flag == "--web") options.server.web_dir = value;
  else if (flag == "--data") options.jobs.data_dir = value;
  else if (flag == "--token") options.server.token = value;
  else if (flag == "--max-jobs") options.jobs.max_jobs = int(integer(flag, value, 1, 64));
  else if (flag == "--max-queue") options.jobs.max_queued = int(integer(flag, value, 0, 100000));
  else if (flag == "--checkpoint-seconds")
    options.jobs.checkpoint_seconds = double(integer(flag, value, 1, 86400));
  else if (flag == "--max-sessions") options.limits.max_sessions = int(integer(flag, value, 1, 1024));
  else if (flag == "--max-depth") options.limits.max_depth = int(integer(flag, value, 0, 64));
  else if (flag == "--keep-jobs") options.jobs.keep_jobs = int(integer(flag, value, 0, 1000000));
  else if (flag == "--jobs-backend") {
    if (value != "local" && value != "slurm")
      throw std::invalid_argument("--jobs-backend: must be \"local\" or \"slurm\", not \"" + value + "\"");
    options.jobs.backend = value == "slurm" ? jobs::JobOptions::Backend::Slurm : jobs::JobOptions::Backend::Local;
  }
  else if (flag == "--slurm-parts") options.jobs.slurm.parts = int(integer(flag, value, 1, 1000));
  else if (flag == "--slurm-scripts") options.jobs.slurm.scripts = value;
  else if (flag == "--prepare-seconds")
    options.server.preparation_seconds = double(integer(flag, value, 1, 3600));
  else throw std::invalid_argument("unknown option " + flag);
}

ServeOptions parse(int argc, char** argv) {
  ServeOptions options;
  options.server.web_dir = GEODESIC_SOURCE_DIR "/web";
  options.jobs.slurm.scripts = GEODESIC_SOURCE_DIR "/deploy/slurm";
  options.jobs.slurm.scene_dir = GEODESIC_SOURCE_DIR "/scenes";
  // The nodes run this very executable (shared storage, as for the data directory).
  options.jobs.slurm.binary = std::filesystem::read_symlink("/proc/self/exe");
  for (const char* flag : kFlags)
    if (const char* value = std::getenv(env_name(flag).c_str()); value && *value)
      apply(options, flag, value);
  for (int i = 0; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) throw std::invalid_argument(flag + ": needs a value");
    apply(options, flag, argv[++i]);
  }
  if (options.jobs.data_dir.empty()) options.jobs.data_dir = default_data_dir();
  // The cluster's nodes find the job folders by this path.
  options.jobs.data_dir = std::filesystem::absolute(options.jobs.data_dir);
  if (options.jobs.backend == jobs::JobOptions::Backend::Slurm &&
      !std::filesystem::is_regular_file(options.jobs.slurm.scripts / "submit.sh"))
    throw std::invalid_argument("--slurm-scripts: no submit.sh in " + options.jobs.slurm.scripts.string());
  // The listener takes addresses only: the name every resolver gives the loopback is mapped.
  if (options.server.host == "localhost") options.server.host = "127.0.0.1";
  if (const std::string why = net::usable_token(options.server.token); !why.empty())
    throw std::invalid_argument("--token: " + why);
  // Anyone who can reach a public address could otherwise use the device and read every job.
  if (options.server.token.empty() && !net::is_loopback(options.server.host))
    throw std::invalid_argument("--token: required when listening on " + options.server.host +
                                " (not a loopback address); or set GEODESIC_TOKEN");
  return options;
}

}  // namespace

int serve_command(int argc, char** argv) {
  const ServeOptions options = parse(argc, argv);

  // Block the stop signals before any thread starts (threads inherit the mask), then wait for
  // them synchronously on this thread: no work in a signal handler.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  // A file-size limit (ulimit -f) then fails the write with EFBIG, which the job reports, rather
  // than killing the daemon.
  std::signal(SIGXFSZ, SIG_IGN);

  RenderService render(options.device, GEODESIC_SOURCE_DIR "/scenes", options.limits);
  render.use_pipeline_cache(options.jobs.data_dir / "pipeline-cache");
  jobs::JobQueue jobs(render, options.jobs);
  net::Server server(render, options.server, &jobs);
  std::printf("geodesic: serving http://%s:%u/ (WebSocket at /ws) on %s, jobs in %s\n",
              options.server.host.c_str(), server.port(), render.stats().device.c_str(),
              options.jobs.data_dir.c_str());
  std::fflush(stdout);

  int signal = 0;
  sigwait(&stop_signals, &signal);
  std::printf("geodesic: %s, shutting down\n", signal == SIGINT ? "SIGINT" : "SIGTERM");
  server.stop();
  return 0;
}

}  // namespace geodesic
