#include "jobs/job.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "scene/render_settings_loader.h"
#include "scene/scene_source.h"

namespace geodesic::jobs {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kStateNames[] = {"queued", "running", "done", "failed", "cancelled"};
constexpr const char* kFormats[] = {"exr", "png", "jpg"};
// Large enough for any real job, small enough that the sample counter cannot overflow.
constexpr int64_t kMaxSpp = 1 << 20;
constexpr double kMaxSeconds = 7 * 24 * 3600.0;

[[noreturn]] void fail(const std::string& field, const std::string& reason) {
  throw RequestError(field + ": " + reason);
}

int integer_in(const Json& body, const char* field, int64_t lo, int64_t hi) {
  const Json& v = body.at(field);
  if (!v.is_number_integer() || v.get<int64_t>() < lo || v.get<int64_t>() > hi)
    fail(field, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return int(v.get<int64_t>());
}

double number_in(const Json& body, const char* field, double lo, double hi) {
  const Json& v = body.at(field);
  if (!v.is_number() || !(v.get<double>() > lo) || !(v.get<double>() <= hi))
    fail(field, "must be a number in (" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v.get<double>();
}

// The body's scene as a source: a bundled name, an inline document, or generator text.
SceneSource scene_source(const Json& body) {
  if (body.contains("generators")) {
    if (!body["generators"].is_string()) fail("generators", "must be the text of a generator file");
    return SceneSource::generator_text(body["generators"].get<std::string>());
  }
  const Json& scene = body["scene"];
  if (scene.is_string()) return SceneSource::bundled(scene.get<std::string>());
  if (scene.is_object()) return SceneSource::inline_document(scene);
  fail("scene", "must be a bundled scene name or a scene document");
}

// Bundled names and generator text are errors of their field already ("scene: unknown bundled
// scene ...", "generators: matrix <i> (line <l>): reason"); a document's name a path inside it,
// which is that path under "scene".
ResolvedScene resolve_source(const SceneSource& source, const RenderService& service) {
  try {
    return service.resolve(source);
  } catch (const SceneError& e) {
    const std::string message = e.what();
    if (source.kind != SceneSource::Kind::Document) throw RequestError(message);
    if (message.starts_with("(root)")) throw RequestError("scene" + message.substr(6));
    throw RequestError("scene." + message);
  }
}

Mat4 parse_camera(const Json& camera) {
  if (!camera.is_array() || camera.size() != 16)
    fail("camera", "must be 16 numbers (the camera isometry, row-major)");
  Mat4 pose;
  for (int i = 0; i < 16; ++i) {
    if (!camera[i].is_number() || !std::isfinite(camera[i].get<double>()))
      fail("camera[" + std::to_string(i) + "]", "must be a finite number");
    pose.m[i / 4][i % 4] = camera[i].get<double>();
  }
  return pose;
}

std::vector<std::string> parse_formats(const Json& formats) {
  if (!formats.is_array() || formats.empty()) fail("formats", "must be a non-empty array");
  std::vector<std::string> result;
  for (size_t i = 0; i < formats.size(); ++i) {
    const std::string field = "formats[" + std::to_string(i) + "]";
    const Json& f = formats[i];
    if (!f.is_string() || std::find(std::begin(kFormats), std::end(kFormats), f) == std::end(kFormats))
      fail(field, "must be one of \"exr\", \"png\", \"jpg\"");
    if (std::find(result.begin(), result.end(), f) != result.end()) fail(field, "repeated");
    result.push_back(f.get<std::string>());
  }
  return result;
}

}  // namespace

const char* state_name(JobState state) { return kStateNames[int(state)]; }

JobState parse_state(const std::string& name) {
  for (int i = 0; i < 5; ++i)
    if (name == kStateNames[i]) return JobState(i);
  throw std::invalid_argument("state: unknown job state \"" + name + "\"");
}

Json JobRequest::to_json() const {
  Json json;
  json["scene"] = scene;
  if (camera) {
    Json numbers = Json::array();
    for (const auto& row : camera->m)
      for (double v : row) numbers.push_back(v);
    json["camera"] = numbers;
  }
  json["width"] = width;
  json["height"] = height;
  if (max_depth) json["max_depth"] = *max_depth;
  if (exposure) json["exposure"] = exposure_to_json(*exposure);
  if (stop.spp) json["spp"] = *stop.spp;
  if (stop.seconds) json["seconds"] = *stop.seconds;
  if (stop.target_error) json["target_error"] = *stop.target_error;
  json["formats"] = formats;
  return json;
}

ValidatedJob validate_job(const Json& body, const RenderService& service) {
  if (!body.is_object()) fail("body", "must be a JSON object");
  static const std::set<std::string> known = {"scene", "generators", "camera", "width", "height",
                                              "max_depth", "spp", "seconds", "target_error",
                                              "formats", "exposure"};
  for (const auto& item : body.items())
    if (!known.contains(item.key())) fail(item.key(), "unknown field");
  if (body.contains("scene") == body.contains("generators"))
    fail(body.contains("scene") ? "generators" : "scene",
         "give exactly one of scene and generators");

  const ServiceLimits& limits = service.limits();
  ResolvedScene resolved = resolve_source(scene_source(body), service);
  ValidatedJob job{JobRequest{}, std::move(resolved.scene)};
  JobRequest& r = job.request;
  // Generator text becomes the default scene of its space (as a WebSocket `open` makes it),
  // stored as that document: a restarted daemon reads it as any other.
  r.scene = body.contains("generators") ? std::move(resolved.generated) : body["scene"];
  auto present = [&](const char* field) { return body.contains(field) && !body[field].is_null(); };
  r.width = present("width") ? integer_in(body, "width", 16, limits.max_width)
                             : job.scene.render.width;
  r.height = present("height") ? integer_in(body, "height", 16, limits.max_height)
                               : job.scene.render.height;
  if (r.width > limits.max_width) fail("width", "the scene's width is over this server's limit");
  if (r.height > limits.max_height) fail("height", "the scene's height is over this server's limit");
  if (present("max_depth")) r.max_depth = integer_in(body, "max_depth", 0, limits.max_depth);
  if (present("exposure")) {
    try {
      r.exposure = exposure_from_json(body["exposure"]);
    } catch (const std::invalid_argument& e) {
      fail("exposure", e.what());
    }
  }
  if (present("camera")) {
    // Checked as a scene's "pose" is: an isometry of the scene's space, within round-off.
    const Mat4 camera = parse_camera(body["camera"]);
    const double error = model::relative_isometry_error(job.scene.geometry, camera);
    if (!(error < 1e-6))
      fail("camera", std::string("not an isometry of ") + geometry_name(job.scene.geometry) +
                         " space (error " + std::to_string(error) + " > 1e-06)");
    r.camera = model::reorthonormalize(job.scene.geometry, camera);
  }

  const int stops = present("spp") + present("seconds") + present("target_error");
  if (stops != 1) fail("spp", "give exactly one stop condition: spp, seconds or target_error");
  if (present("spp")) r.stop.spp = uint32_t(integer_in(body, "spp", 1, kMaxSpp));
  if (present("seconds")) r.stop.seconds = number_in(body, "seconds", 0, kMaxSeconds);
  if (present("target_error")) r.stop.target_error = number_in(body, "target_error", 0, 1);
  r.formats = present("formats") ? parse_formats(body["formats"])
                                 : std::vector<std::string>(std::begin(kFormats), std::end(kFormats));

  job.scene.render.width = r.width;
  job.scene.render.height = r.height;
  if (r.max_depth) job.scene.render.max_depth = *r.max_depth;
  if (r.exposure) job.scene.render.exposure = *r.exposure;
  if (r.camera) job.scene.camera.pose = *r.camera;
  return job;
}

ConvergenceLog series_from_json(const Json& series) {
  if (!series.is_array()) throw std::invalid_argument("series: not an array");
  ConvergenceLog log;
  for (const Json& point : series)
    log.record({point.at("seconds").get<double>(), point.at("spp").get<uint32_t>(),
                point.at("estimated_error").is_null() ? -1.0
                                                      : point["estimated_error"].get<double>()});
  return log;
}

std::string without_data_dir(std::string message, const std::filesystem::path& job_dir) {
  const std::string data_dir = job_dir.parent_path().parent_path().string() + "/";
  for (std::size_t at = message.find(data_dir); at != std::string::npos; at = message.find(data_dir))
    message.erase(at, data_dir.size());
  return message;
}

std::string job_url(int64_t id) { return "/api/jobs/" + std::to_string(id); }

std::vector<std::string> stored_formats(const Json& request) {
  std::vector<std::string> formats;
  if (const auto it = request.find("formats"); it != request.end() && it->is_array())
    for (const Json& format : *it)
      if (format.is_string()) formats.push_back(format.get<std::string>());
  return formats;
}

Json JobRecord::status_json(bool detail) const {
  Json json;
  json["id"] = id;
  json["url"] = job_url(id);
  json["state"] = state_name(state);
  // The request may be an empty object: a damaged stored row (job_store.cpp) reads as failed.
  const Json scene = request.value("scene", Json());
  json["scene"] = scene.is_string() ? scene
                  : scene.is_object() && scene.contains("name") && scene["name"].is_string()
                      ? scene["name"]
                      : Json("document");
  json["width"] = request.value("width", Json());
  json["height"] = request.value("height", Json());
  json["created"] = created;
  json["progress"] = progress;
  json["samples"] = samples;
  json["elapsed"] = elapsed;
  json["estimated_error"] = error >= 0 ? Json(error) : Json(nullptr);
  json["checkpoint_samples"] = checkpoint_samples;
  json["non_finite_samples"] = non_finite_samples;
  json["truncated_geodesics"] = truncated_geodesics;
  json["message"] = message.empty() ? Json(nullptr) : Json(message);
  Json results = Json::object();
  if (state == JobState::Done)
    for (const std::string& format : stored_formats(request))
      results[format] = job_url(id) + "/result." + format;
  json["results"] = results;
  json["report"] = {{"json", job_url(id) + "/report.json"}, {"csv", job_url(id) + "/report.csv"}};
  if (detail) {
    json["request"] = request;
    json["series"] = series.to_json()["series"];
  }
  return json;
}

}  // namespace geodesic::jobs
