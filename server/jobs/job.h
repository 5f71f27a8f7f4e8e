// A render job: what was asked for (JobRequest, validated from the POST /api/jobs body) and
// what it has become (JobRecord: state, progress, the error series). Plain data; the store
// persists it and the queue drives it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/vec.h"
#include "render/prepare/convergence.h"
#include "render/service/render_service.h"

namespace geodesic::jobs {

enum class JobState { Queued, Running, Done, Failed, Cancelled };

const char* state_name(JobState state);
JobState parse_state(const std::string& name);  // throws std::invalid_argument
inline bool finished(JobState state) {
  return state == JobState::Done || state == JobState::Failed || state == JobState::Cancelled;
}

// A request that cannot be accepted; the message is "<field>: <reason>" (400).
class RequestError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct JobRequest {
  nlohmann::ordered_json scene;  // a bundled name (string) or an inline document (object)
  std::optional<Mat4> camera;    // the camera isometry, as `frame` messages give it
  int width = 0, height = 0;
  std::optional<int> max_depth;
  std::optional<Exposure> exposure;  // of the PNG and JPEG results; the scene's when absent
  StopCondition stop;            // exactly one field set
  std::vector<std::string> formats;  // of "exr", "png", "jpg"

  nlohmann::ordered_json to_json() const;  // the canonical form, as stored
};

// Validates a POST body (already parsed as JSON) against the service's limits, resolving the
// scene as the WebSocket `open` does; throws RequestError naming the field. Returns the
// request and the scene it names, with the request's size and depth applied.
struct ValidatedJob {
  JobRequest request;
  Scene scene;
};
ValidatedJob validate_job(const nlohmann::ordered_json& body, const RenderService& service);

struct JobRecord {
  int64_t id = 0;
  JobState state = JobState::Queued;
  nlohmann::ordered_json request;  // JobRequest::to_json(): validate_job() reads it back
  std::string created;  // ISO 8601, UTC
  uint32_t samples = 0;
  double elapsed = 0;    // seconds of rendering, over every run of the job
  double error = -1;     // estimated relative RMS error; < 0 while unknown
  double progress = 0;   // in [0, 1], towards the stop condition
  uint32_t checkpoint_samples = 0;  // samples in the last checkpoint (0: none)
  // Over every run of the job: samples dropped as NaN/Inf, geodesics cut off at max_crossings.
  uint64_t non_finite_samples = 0, truncated_geodesics = 0;
  std::string message;   // why it failed
  ConvergenceLog series;

  // GET /api/jobs lists these; GET /api/jobs/{id} adds the request and the series (`detail`).
  nlohmann::ordered_json status_json(bool detail) const;
};

// The inverse of ConvergenceLog::to_json()["series"] (the store keeps the series as JSON).
ConvergenceLog series_from_json(const nlohmann::ordered_json& series);

// The result formats of a stored request (none when it has no valid list).
std::vector<std::string> stored_formats(const nlohmann::ordered_json& request);

// Messages go to clients: where the data directory lies on the server is not theirs to know
// ("<data>/jobs/2/result.exr: File too large" -> "jobs/2/result.exr: File too large").
std::string without_data_dir(std::string message, const std::filesystem::path& job_dir);

// "/api/jobs/<id>"
std::string job_url(int64_t id);

}  // namespace geodesic::jobs
