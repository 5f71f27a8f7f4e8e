#include "jobs/slurm_job.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "jobs/durable_file.h"
#include "jobs/subprocess.h"
#include "render/prepare/image_io.h"

namespace geodesic::jobs {
namespace {

using Json = nlohmann::ordered_json;

double unix_time() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The last non-empty line of what a step printed (its error, when it failed).
std::string last_line(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last;
}

// Slurm states a job is still in the queue with (squeue's %T).
bool waiting_or_running(const std::string& state) {
  static const std::set<std::string> states = {
      "PENDING", "RUNNING", "CONFIGURING", "COMPLETING", "REQUEUED", "REQUEUE_HOLD",
      "REQUEUE_FED", "RESIZING", "SUSPENDED", "STOPPED", "SIGNALING", "STAGE_OUT"};
  return states.contains(state);
}

std::string exposure_text(const Exposure& exposure) {
  if (exposure.automatic) return "auto";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", exposure.stops);
  return text;
}

std::string camera_text(const Mat4& pose) {
  std::string text;
  char number[32];
  for (const auto& row : pose.m)
    for (double v : row) {
      std::snprintf(number, sizeof number, "%.17g", v);
      text += (text.empty() ? "" : ",") + std::string(number);
    }
  return text;
}

}  // namespace

int slurm_parts(uint32_t spp, int most) {
  for (int parts = std::max(1, most); parts > 1; --parts)
    if (spp % uint32_t(parts) == 0) return parts;
  return 1;
}

SlurmJob::SlurmJob(RenderService& service, JobStore& store, JobRecord job,
                   std::filesystem::path dir, SlurmOptions options)
    : JobExecution(store, std::move(job), std::move(dir)),
      service_(service),
      options_(std::move(options)) {
  thread_ = std::thread([this] { run(); });
}

SlurmJob::~SlurmJob() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void SlurmJob::remove_files(JobState state) {
  std::error_code ignored;
  if (state == JobState::Failed || state == JobState::Cancelled) std::filesystem::remove_all(dir_, ignored);
}

void SlurmJob::run() {
  try {
    const Json ids = std::filesystem::exists(dir_ / "slurm.json")
                         ? Json::parse(read_text(dir_ / "slurm.json"))
                         : Json();
    if (ids.is_object()) {  // submitted before the daemon last stopped
      parts_job_ = ids.at("parts_job");
      merge_job_ = ids.at("merge_job");
      parts_ = ids.at("parts");
      samples_per_part_ = ids.at("samples_per_part");
      submitted_ = ids.at("submitted");
    } else if (!cancel_) {
      submit();
    }
    while (true) {
      if (cancel_) {
        if (!parts_job_.empty()) run_command({"scancel", parts_job_, merge_job_});
        save(JobState::Cancelled);
        break;
      }
      if (!active()) {
        collect();
        break;
      }
      progress();
      std::unique_lock lock(mutex_);
      wake_.wait_for(lock, std::chrono::duration<double>(options_.poll_seconds),
                     [&] { return stop_ || cancel_; });
      if (stop_) break;
    }
  } catch (const std::exception& e) {
    if (!parts_job_.empty()) run_command({"scancel", parts_job_, merge_job_});
    save(JobState::Failed, std::string("slurm: ") + e.what());
  }
  finished_ = true;
}

void SlurmJob::submit() {
  const ValidatedJob job = validate_job(job_.request, service_);
  if (!job.request.stop.spp) throw RequestError("spp: the slurm backend splits a sample count");
  const uint32_t spp = *job.request.stop.spp;
  parts_ = slurm_parts(spp, options_.parts);
  samples_per_part_ = spp / uint32_t(parts_);
  std::filesystem::create_directories(dir_);

  // A bundled scene is rendered from its own file; a document from a copy in the job's folder,
  // its files (meshes, generator files) found among the bundled scenes as the daemon finds them.
  std::filesystem::path scene = options_.scene_dir / (job.request.scene.is_string()
                                                          ? job.request.scene.get<std::string>() + ".json"
                                                          : std::string());
  std::vector<std::string> render_options = {
      "--width", std::to_string(job.request.width), "--height", std::to_string(job.request.height),
      "--max-depth", std::to_string(job.scene.render.max_depth)};
  if (!job.request.scene.is_string()) {
    scene = dir_ / "scene.json";
    write_durably(scene, [&](const std::filesystem::path& file) {
      std::ofstream(file) << job.request.scene.dump() << "\n";
    });
    render_options.insert(render_options.end(), {"--scene-dir", options_.scene_dir.string()});
  }
  if (job.request.camera) render_options.insert(render_options.end(), {"--camera", camera_text(*job.request.camera)});

  std::string images;
  for (const std::string& format : job.request.formats) images += (images.empty() ? "" : " ") + ("result." + format);
  std::vector<std::string> argv = {"bash", (options_.scripts / "submit.sh").string(), scene.string(),
                                   std::to_string(parts_), std::to_string(samples_per_part_),
                                   dir_.string(), images};
  argv.insert(argv.end(), render_options.begin(), render_options.end());
  const CommandResult submitted =
      run_command(argv, {{"GEODESIC_BIN", options_.binary.string()},
                         {"GEODESIC_MERGE_OPTIONS", "--exposure " + exposure_text(job.scene.render.exposure)}},
                  60);
  std::istringstream ids(submitted.out);
  if (submitted.exit_code != 0 || !(ids >> parts_job_ >> merge_job_)) {
    parts_job_.clear();
    throw std::runtime_error("submit.sh " + std::string(submitted.timed_out ? "timed out" : "failed") +
                             ": " + last_line(submitted.err));
  }
  submitted_ = unix_time();
  const Json record = {{"parts_job", parts_job_}, {"merge_job", merge_job_}, {"parts", parts_},
                       {"samples_per_part", samples_per_part_}, {"submitted", submitted_}};
  write_durably(dir_ / "slurm.json", [&](const std::filesystem::path& file) {
    std::ofstream(file) << record.dump() << "\n";
  });
  save(JobState::Running);
}

bool SlurmJob::active() {
  const CommandResult queue =
      run_command({"squeue", "--noheader", "--format=%T", "--jobs=" + parts_job_ + "," + merge_job_});
  if (queue.exit_code != 0) {
    // Jobs that ended long enough ago are forgotten by the controller: "Invalid job id".
    if (queue.err.find("Invalid job id") != std::string::npos) return false;
    throw std::runtime_error("squeue " + std::string(queue.timed_out ? "timed out" : "failed") +
                             ": " + last_line(queue.err));
  }
  std::istringstream states(queue.out);
  for (std::string state; states >> state;)
    if (waiting_or_running(state)) return true;
  return false;
}

void SlurmJob::progress() {
  int done = 0;
  for (int i = 0; i < parts_; ++i) done += std::filesystem::exists(dir_ / ("part-" + std::to_string(i) + ".exr"));
  std::lock_guard lock(mutex_);
  job_.samples = uint32_t(done) * samples_per_part_;
  job_.elapsed = unix_time() - submitted_;
  job_.progress = 0.99 * done / std::max(1, parts_);
}

void SlurmJob::collect() {
  for (const std::string& format : stored_formats(job_.request)) {
    const std::filesystem::path result = dir_ / ("result." + format);
    if (std::filesystem::exists(result)) {
      read_image(result);  // a result the merge left half written fails the job here
      continue;
    }
    // The first part that wrote no accumulation says why; else the merge does.
    std::string why;
    for (int i = 0; i < parts_ && why.empty(); ++i)
      if (!std::filesystem::exists(dir_ / ("part-" + std::to_string(i) + ".exr")))
        why = "part " + std::to_string(i) + ": " + last_line(read_text(dir_ / ("part-" + std::to_string(i) + ".log")));
    if (why.empty()) why = "merge: " + last_line(read_text(dir_ / "merge.log"));
    throw std::runtime_error("no " + result.filename().string() + " after the cluster's jobs " +
                             parts_job_ + " and " + merge_job_ + " ended; " + why);
  }
  const Json merged = Json::parse(read_text(dir_ / "merge-report.json"));
  uint64_t non_finite = 0, truncated = 0;
  for (int i = 0; i < parts_; ++i) {
    const Json part = Json::parse(read_text(dir_ / ("part-" + std::to_string(i) + ".json")));
    non_finite += part.at("non_finite_samples").get<uint64_t>();
    truncated += part.at("truncated_geodesics").get<uint64_t>();
  }
  {
    std::lock_guard lock(mutex_);
    job_.samples = merged.at("samples");
    job_.error = merged.at("estimated_error").is_null() ? -1.0 : merged["estimated_error"].get<double>();
    job_.elapsed = unix_time() - submitted_;
    job_.progress = 1;
    job_.non_finite_samples = non_finite;
    job_.truncated_geodesics = truncated;
    job_.series.record({job_.elapsed, job_.samples, job_.error});
  }
  service_.count_background(non_finite, truncated);
  save(JobState::Done);
}

}  // namespace geodesic::jobs
