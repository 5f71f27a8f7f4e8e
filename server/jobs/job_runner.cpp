#include "jobs/job_runner.h"

#include <algorithm>
#include <chrono>
#include <memory>

#include "jobs/checkpoint.h"
#include "jobs/durable_file.h"
#include "render/image_io.h"
#include "render/renderer.h"

namespace geodesic::jobs {
namespace {

using Clock = std::chrono::steady_clock;

// A series point at most this often (and at the end), so long jobs keep a short report.
constexpr double kSeriesInterval = 0.25;
// Passes of more samples than this are not faster, and a seconds stop would overshoot.
constexpr uint32_t kMaxBatch = 256;
// Rows of the first band, before the cost of a row is known (a small start keeps the first turn
// within about a slice on any image).
constexpr int kFirstBand = 8;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

}  // namespace

JobRunner::JobRunner(RenderService& service, JobStore& store, JobRecord job,
                     std::filesystem::path dir, double checkpoint_seconds)
    : service_(service),
      store_(store),
      dir_(std::move(dir)),
      checkpoint_seconds_(checkpoint_seconds),
      job_(std::move(job)) {
  thread_ = std::thread([this] { run(); });
}

JobRunner::~JobRunner() {
  stop_ = true;
  thread_.join();
}

bool JobRunner::cancel() {
  {
    std::lock_guard lock(mutex_);
    if (jobs::finished(job_.state)) return false;
    job_.state = JobState::Cancelled;
  }
  cancel_ = true;
  save(JobState::Cancelled);
  return true;
}

JobRecord JobRunner::status() const {
  std::lock_guard lock(mutex_);
  return job_;
}

void JobRunner::run() {
  try {
    render();
  } catch (const std::exception& e) {
    save(JobState::Failed, e.what());
  }
  finished_ = true;
}

void JobRunner::save(JobState state, const std::string& message) {
  JobRecord copy;
  {
    std::lock_guard lock(mutex_);
    if (job_.state == JobState::Cancelled) state = JobState::Cancelled;  // a cancel wins
    job_.state = state;
    job_.message = message;
    copy = job_;
  }
  if (jobs::finished(state)) std::filesystem::remove(dir_ / "checkpoint.bin");
  store_.update(copy);
}

void JobRunner::render() {
  const ValidatedJob job = validate_job(job_.request, service_);
  const StopCondition& stop = job.request.stop;
  const int width = job.request.width, height = job.request.height;
  std::filesystem::create_directories(dir_);
  const std::filesystem::path checkpoint_file = dir_ / "checkpoint.bin";
  const std::optional<Checkpoint> checkpoint = read_checkpoint(checkpoint_file);

  std::unique_ptr<Renderer> renderer;
  // Vulkan objects are made and freed only while this job holds the device, on every way out.
  auto release = [&] {
    if (renderer && !service_.run_background([&](VulkanContext&) { renderer.reset(); }))
      renderer.reset();  // the service is being destroyed: no session renders any more
  };
  struct ReleaseOnExit {
    decltype(release)& free_renderer;
    ~ReleaseOnExit() { free_renderer(); }
  } release_on_exit{release};
  if (!service_.run_background([&](VulkanContext& ctx) {
        renderer = std::make_unique<Renderer>(ctx, job.scene);
        renderer->set_view(job.scene.camera.pose, width, height);
        if (checkpoint) renderer->restore(checkpoint->samples, checkpoint->sums);
      }))
    return;

  const double elapsed_before = checkpoint ? checkpoint->elapsed : 0;
  {
    std::lock_guard lock(mutex_);
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
  double last_point = -kSeriesInterval;
  uint32_t batch = 1, next_row = 0;
  double seconds_per_pixel_sample = 0;
  while (!stop_) {
    if (cancel_) {
      release();
      return save(JobState::Cancelled);
    }
    bool pass_done = false;
    const bool had_turn = service_.run_background([&](VulkanContext&) {
      if (next_row == 0 && stop.spp)  // the last pass ends exactly at the spp asked for
        batch = std::min(batch, *stop.spp - renderer->samples());
      const double row_cost = seconds_per_pixel_sample * width * batch;
      const int rows = row_cost > 0 ? std::clamp(int(RenderService::kSliceSeconds / row_cost), 1, height)
                                    : kFirstBand;
      const int band = std::min(rows, height - int(next_row));
      const auto start = Clock::now();
      renderer->render_rows(batch, next_row, uint32_t(band));
      const double took = seconds_since(start);
      const double cost = took / (double(batch) * width * band);
      seconds_per_pixel_sample =
          seconds_per_pixel_sample > 0 ? 0.7 * seconds_per_pixel_sample + 0.3 * cost : cost;
      next_row += uint32_t(band);
      if (int(next_row) < height) return;
      renderer->finish_pass(batch);
      next_row = 0;
      pass_done = true;
      if (band == height) {  // the whole pass fit in one turn: size the next one to a turn
        if (took < RenderService::kSliceSeconds / 2 && batch < kMaxBatch) batch *= 2;
        else if (took > RenderService::kSliceSeconds * 2 && batch > 1) batch /= 2;
      }
    });
    if (!had_turn) break;  // the service is stopping
    if (!pass_done) continue;

    // Between passes the accumulation is this thread's alone: no device turn needed to read it.
    const ErrorSample now{elapsed_before + seconds_since(started), renderer->samples(),
                          renderer->estimated_error()};
    const bool reached = stop.reached(now);
    {
      std::lock_guard lock(mutex_);
      job_.samples = now.spp;
      job_.elapsed = now.seconds;
      job_.error = now.error;
      job_.progress = reached ? 1.0 : stop.progress(now);
      if (reached || now.seconds - last_point >= kSeriesInterval) {
        job_.series.record(now);
        last_point = now.seconds;
      }
    }
    if (reached) {
      const Image image = renderer->image();
      release();
      for (const std::string& format : job.request.formats)
        write_durably(dir_ / ("result." + format),
                      [&](const std::filesystem::path& file) { write_image(file, image); });
      return save(JobState::Done);
    }
    if (seconds_since(last_checkpoint) >= checkpoint_seconds_) {
      write_checkpoint(checkpoint_file, now.spp, now.seconds, width, height,
                       renderer->accumulation());
      last_checkpoint = Clock::now();
      {
        std::lock_guard lock(mutex_);
        job_.checkpoint_samples = now.spp;
      }
      save(JobState::Running);
    }
  }
  // A shutdown: the store keeps the job running, to resume from its checkpoint.
}

}  // namespace geodesic::jobs
