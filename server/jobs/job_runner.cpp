#include "jobs/job_runner.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "jobs/checkpoint.h"
#include "jobs/durable_file.h"
#include "render/prepare/exposure.h"
#include "render/prepare/image_io.h"
#include "render/service/pass_slicer.h"
#include "render/device/renderer.h"
#include "render/device/vulkan_context.h"

namespace geodesic::jobs {
namespace {

using Clock = std::chrono::steady_clock;

// A series point at most this often (and at the end), so long jobs keep a short report.
constexpr double kSeriesInterval = 0.25;
// Device losses a job starts over after (from its checkpoint, on the service's new device)
// before it fails.
constexpr int kDeviceLossRetries = 3;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

}  // namespace

JobRunner::JobRunner(RenderService& service, JobStore& store, JobRecord job,
                     std::filesystem::path dir, double checkpoint_seconds)
    : JobExecution(store, std::move(job), std::move(dir)),
      service_(service),
      checkpoint_seconds_(checkpoint_seconds) {
  thread_ = std::thread([this] { run(); });
}

JobRunner::~JobRunner() {
  stop_ = true;
  thread_.join();
}

void JobRunner::run() {
  for (int losses = 0;; ++losses) {
    try {
      render();
    } catch (const VulkanError& e) {
      if (e.result() == VK_ERROR_DEVICE_LOST && losses < kDeviceLossRetries) {
        std::fprintf(stderr, "geodesic: job %lld: %s; starting over from its checkpoint\n",
                     static_cast<long long>(job_.id), e.what());
        continue;
      }
      save(JobState::Failed, e.what());
    } catch (const std::exception& e) {
      save(JobState::Failed, e.what());
    }
    break;
  }
  finished_ = true;
}

void JobRunner::remove_files(JobState state) {
  std::error_code ignored;
  if (state == JobState::Failed) std::filesystem::remove_all(dir_, ignored);  // results half written
  else if (jobs::finished(state)) std::filesystem::remove(dir_ / "checkpoint.bin", ignored);
}

void JobRunner::render() {
  const ValidatedJob job = validate_job(job_.request, service_);
  const StopCondition& stop = job.request.stop;
  const int width = job.request.width, height = job.request.height;
  std::filesystem::create_directories(dir_);
  const std::filesystem::path checkpoint_file = dir_ / "checkpoint.bin";
  const uint64_t fingerprint = checkpoint_fingerprint(job_.request.dump(), width, height,
                                                      job.scene.render.seed);
  std::optional<Checkpoint> checkpoint;
  try {
    checkpoint = read_checkpoint(checkpoint_file, fingerprint);
    if (checkpoint && (checkpoint->width != width || checkpoint->height != height))
      throw CheckpointError("checkpoint: its size differs from the job's");
    if (checkpoint && stop.spp && checkpoint->samples > *stop.spp)
      throw CheckpointError("checkpoint: more samples than the job asks for");
  } catch (const CheckpointError& e) {
    // Damaged, or another job's: the job starts over from zero with its intact request.
    std::fprintf(stderr, "geodesic: job %lld: %s; starting from zero\n",
                 static_cast<long long>(job_.id), e.what());
    std::error_code ignored;
    std::filesystem::remove(checkpoint_file, ignored);
  }

  std::unique_ptr<Renderer> renderer;
  // The renderer is built and freed beside the rendering, not in a device turn (the sessions
  // go on meanwhile), and freed on every way out.
  auto release = [&] {
    if (renderer && !service_.run_beside([&](VulkanContext&) { renderer.reset(); }))
      renderer.reset();  // the service is being destroyed: no session renders any more
  };
  struct ReleaseOnExit {
    decltype(release)& free_renderer;
    ~ReleaseOnExit() { free_renderer(); }
  } release_on_exit{release};
  if (!service_.run_beside([&](VulkanContext& ctx) {
        renderer = std::make_unique<Renderer>(ctx, job.scene);
        renderer->set_view(job.scene.camera.pose, width, height);
        if (checkpoint) renderer->restore(checkpoint->samples, checkpoint->sums);
      }))
    return;
  service_.warm_up(*renderer, job.scene);  // its first slice would compile it, holding the device

  const double elapsed_before = checkpoint ? checkpoint->elapsed : 0;
  uint64_t non_finite_before = 0, truncated_before = 0;  // counted by earlier runs
  {
    std::lock_guard lock(mutex_);
    non_finite_before = job_.non_finite_samples;
    truncated_before = job_.truncated_geodesics;
    // Samples after the checkpoint were lost with the process: the series goes back to it.
    const uint32_t kept = checkpoint ? checkpoint->samples : 0;
    ConvergenceLog series;
    for (const ErrorSample& point : job_.series.samples())
      if (point.spp <= kept) series.record(point);
    job_.series = std::move(series);
    job_.samples = kept;
    job_.elapsed = elapsed_before;
    job_.checkpoint_samples = kept;
  }
  save(JobState::Running);

  const auto started = Clock::now();
  auto last_checkpoint = started;
  uint32_t checkpointed = checkpoint ? checkpoint->samples : 0;
  auto save_checkpoint = [&](const ErrorSample& pass_end) {
    write_checkpoint(checkpoint_file, fingerprint, pass_end.spp, pass_end.seconds, width, height,
                     renderer->accumulation());
    last_checkpoint = Clock::now();
    checkpointed = pass_end.spp;
    {
      std::lock_guard lock(mutex_);
      job_.checkpoint_samples = pass_end.spp;
    }
    save(JobState::Running);
  };
  double last_point = -kSeriesInterval;
  PassSlicer slicer(RenderService::kSliceSeconds);
  ErrorSample now{elapsed_before, checkpointed, -1};  // at the end of the last whole pass
  // A stop (the daemon shutting down) first finishes the pass in progress.
  while (!stop_ || slicer.in_pass()) {
    if (cancel_) {
      release();
      return save(JobState::Cancelled);
    }
    // The last pass ends exactly at the spp asked for; a checkpoint that holds them all needs
    // no pass.
    const bool all_there = stop.spp && renderer->samples() >= *stop.spp;
    if (!slicer.in_pass() && stop.spp && !all_there)
      slicer.limit_batch(*stop.spp - renderer->samples());
    bool pass_done = all_there && !slicer.in_pass();
    if (!pass_done) {
      const bool had_turn = service_.run_background(
          [&](VulkanContext&) { pass_done = slicer.render_slice(*renderer); });
      if (!had_turn) break;  // the service is stopping
      if (!pass_done) continue;
    }

    // Between passes the accumulation is this thread's alone: no device turn needed to read it.
    now = {elapsed_before + seconds_since(started), renderer->samples(),
           renderer->estimated_error()};
    const bool reached = stop.reached(now);
    const uint64_t non_finite = non_finite_before + renderer->non_finite_samples();
    const uint64_t truncated = truncated_before + renderer->trace_counters().truncated_rays;
    uint64_t new_non_finite = 0, new_truncated = 0;
    {
      std::lock_guard lock(mutex_);
      new_non_finite = non_finite - job_.non_finite_samples;
      new_truncated = truncated - job_.truncated_geodesics;
      job_.non_finite_samples = non_finite;
      job_.truncated_geodesics = truncated;
      job_.samples = now.spp;
      job_.elapsed = now.seconds;
      job_.error = now.error;
      job_.progress = reached ? 1.0 : stop.progress(now);
      if (reached || now.seconds - last_point >= kSeriesInterval) {
        job_.series.record(now);
        last_point = now.seconds;
      }
    }
    service_.count_background(new_non_finite, new_truncated);
    if (reached) {
      const Image image = renderer->image();
      const float scale = exposure_scale(exposure_stops(job.scene.render.exposure, image));
      release();
      for (const std::string& format : job.request.formats)
        write_durably(dir_ / ("result." + format), [&](const std::filesystem::path& file) {
          write_image(file, image, scale);
          // A writer that did not report a short write on a full disk is caught here.
          const Image written = read_image(file);
          if (written.width != image.width || written.height != image.height)
            throw std::runtime_error(file.string() + ": reads back as another image");
        });
      return save(JobState::Done);
    }
    if (seconds_since(last_checkpoint) >= checkpoint_seconds_) save_checkpoint(now);
  }
  // A shutdown: the store keeps the job running, to resume from a checkpoint of every sample
  // rendered (a pass cut short by the service stopping is not one: it goes back to the last).
  if (!slicer.in_pass() && now.spp > checkpointed) save_checkpoint(now);
}

}  // namespace geodesic::jobs
