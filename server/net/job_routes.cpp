#include "net/job_routes.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

namespace geodesic::net {
namespace {

using namespace geodesic::jobs;
using http::status;
using Json = nlohmann::ordered_json;

constexpr std::string_view kPrefix = "/api/jobs";
constexpr int64_t kMaxPage = 1000;

struct Download {
  const char* name;  // after "/api/jobs/<id>/"
  const char* mime;
};
constexpr Download kDownloads[] = {
    {"result.exr", "image/x-exr"},         {"result.png", "image/png"},
    {"result.jpg", "image/jpeg"},          {"report.json", "application/json"},
    {"report.csv", "text/csv; charset=utf-8"},
};

std::optional<int64_t> parse_id(std::string_view text) {
  int64_t id = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (ec != std::errc() || end != text.data() + text.size() || id <= 0) return std::nullopt;
  return id;
}

Response not_found(const Request& request, int64_t id) {
  return net::json_error(request, status::not_found, "id: no job " + std::to_string(id));
}

Response submit(const Request& request, JobQueue& queue) {
  Json body;
  try {
    body = Json::parse(request.body());
  } catch (const Json::exception& e) {  // parse_error, or out_of_range for 1e400
    return net::json_error(request, status::bad_request, std::string("body: invalid JSON: ") + e.what());
  }
  try {
    const JobRecord job = queue.submit(body);
    Response response = net::json_response(request, {{"id", job.id}, {"url", job_url(job.id)}},
                                           status::accepted);
    response.set(net::http::field::location, job_url(job.id));
    return response;
  } catch (const RequestError& e) {
    return net::json_error(request, status::bad_request, e.what());
  } catch (const QueueFull& e) {
    return net::json_error(request, status::too_many_requests, e.what());
  } catch (const std::runtime_error& e) {  // the store cannot write (a full disk)
    Response response = net::json_error(request, status::service_unavailable,
                                        std::string("store: the job was not stored: ") + e.what());
    response.set(net::http::field::retry_after, "60");
    return response;
  }
}

// ?name=<digits> in the target; nullopt when absent; throws RequestError when malformed.
std::optional<int64_t> query_integer(const Request& request, std::string_view name, int64_t max) {
  const std::string_view target(request.target().data(), request.target().size());
  const std::string_view value = net::query_parameter(target, name);
  if (value.empty() && target.find(std::string(name) + "=") == std::string_view::npos) return std::nullopt;
  int64_t number = -1;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), number);
  if (ec != std::errc() || end != value.data() + value.size() || number < 0 || number > max)
    throw RequestError(std::string(name) + ": must be an integer in [0, " + std::to_string(max) + "]");
  return number;
}

// GET /api/jobs[?limit=N][&after=ID]: a page in id order, and the `next` page's link when the
// page is full.
Response list_jobs(const Request& request, JobQueue& queue) {
  std::optional<int64_t> limit, after;
  try {
    limit = query_integer(request, "limit", kMaxPage);
    after = query_integer(request, "after", INT64_MAX);
  } catch (const RequestError& e) {
    return net::json_error(request, status::bad_request, e.what());
  }
  if (limit && *limit == 0) return net::json_error(request, status::bad_request,
                                                   "limit: must be an integer in [1, " +
                                                       std::to_string(kMaxPage) + "]");
  Json jobs = Json::array();
  const std::vector<JobRecord> page = queue.list(after.value_or(0), int(limit.value_or(0)));
  for (const JobRecord& job : page) jobs.push_back(job.status_json(/*detail=*/false));
  Json body = {{"jobs", jobs}};
  if (limit && !page.empty() && int64_t(page.size()) == *limit)
    body["next"] = std::string(kPrefix) + "?limit=" + std::to_string(*limit) +
                   "&after=" + std::to_string(page.back().id);
  return net::json_response(request, body);
}

Response report(const Request& request, const JobRecord& job, bool csv) {
  if (csv) return net::make_response(request, status::ok, "text/csv; charset=utf-8", job.series.to_csv());
  Json body = job.status_json(/*detail=*/false);
  body["stop"] = Json::object();
  for (const char* field : {"spp", "seconds", "target_error"})
    if (job.request.contains(field)) body["stop"][field] = job.request[field];
  body["series"] = job.series.to_json()["series"];
  return net::json_response(request, body);
}

Response download(const Request& request, JobQueue& queue, const JobRecord& job,
                  const Download& what) {
  const std::string_view name = what.name;
  if (name.starts_with("report.")) return report(request, job, name.ends_with(".csv"));
  const std::string format(name.substr(name.find('.') + 1));
  const std::vector<std::string> formats = stored_formats(job.request);
  if (std::find(formats.begin(), formats.end(), format) == formats.end())
    return net::json_error(request, status::not_found, "format: job " + std::to_string(job.id) +
                                                           " was not asked for " + format);
  if (job.state != JobState::Done)
    return net::json_error(request, status::conflict,
                           std::string("state: job is ") + state_name(job.state) + ", not done");
  std::ifstream file(queue.result_file(job.id, format), std::ios::binary);
  if (!file) return net::json_error(request, status::internal_server_error, "result: missing file");
  std::ostringstream bytes;
  bytes << file.rdbuf();
  Response response = net::make_response(request, status::ok, what.mime, std::move(bytes).str());
  response.set(net::http::field::content_disposition,
               "attachment; filename=\"job-" + std::to_string(job.id) + "." + format + "\"");
  return response;
}

// /api/jobs/<id>[/<download>]
Response one_job(const Request& request, JobQueue& queue, std::string_view rest) {
  const size_t slash = rest.find('/');
  const std::optional<int64_t> id = parse_id(rest.substr(0, slash));
  if (!id) return net::json_error(request, status::not_found, "id: not a job id");
  const auto method = request.method();
  if (slash == std::string_view::npos) {
    const std::string_view target(request.target().data(), request.target().size());
    if (method == net::http::verb::delete_ && net::query_parameter(target, "remove") == "true") {
      try {
        if (!queue.remove(*id)) return not_found(request, *id);
        return net::json_response(request, {{"id", *id}, {"removed", true}});
      } catch (const AlreadyFinished& e) {
        return net::json_error(request, status::conflict, e.what());
      }
    }
    if (method == net::http::verb::delete_) {
      try {
        const std::optional<JobRecord> job = queue.cancel(*id);
        if (!job) return not_found(request, *id);
        return net::json_response(request, job->status_json(false));
      } catch (const AlreadyFinished& e) {
        return net::json_error(request, status::conflict, e.what());
      }
    }
    if (method != net::http::verb::get && method != net::http::verb::head)
      return net::method_not_allowed(request, "GET, HEAD, DELETE");
    const std::optional<JobRecord> job = queue.get(*id);
    if (!job) return not_found(request, *id);
    return net::json_response(request, job->status_json(/*detail=*/true));
  }
  const std::string_view name = rest.substr(slash + 1);
  const Download* what = nullptr;
  for (const Download& d : kDownloads)
    if (name == d.name) what = &d;
  if (!what) return net::json_error(request, status::not_found, "path: no such job resource");
  if (method != net::http::verb::get && method != net::http::verb::head)
    return net::method_not_allowed(request, "GET, HEAD");
  const std::optional<JobRecord> job = queue.get(*id);
  if (!job) return not_found(request, *id);
  return download(request, queue, *job, *what);
}

}  // namespace

std::optional<Response> answer_jobs(const Request& request, std::string_view path, JobQueue& queue) {
  if (!path.starts_with(kPrefix)) return std::nullopt;
  std::string_view rest = path.substr(kPrefix.size());
  if (rest.empty() || rest == "/") {
    if (request.method() == net::http::verb::post) return submit(request, queue);
    if (request.method() != net::http::verb::get && request.method() != net::http::verb::head)
      return net::method_not_allowed(request, "GET, HEAD, POST");
    return list_jobs(request, queue);
  }
  if (rest.front() != '/') return std::nullopt;  // e.g. /api/jobsx: not ours
  return one_job(request, queue, rest.substr(1));
}

}  // namespace geodesic::net
