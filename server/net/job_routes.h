// The jobs API over HTTP (docs/protocol.md, proto/openapi.json): POST and GET /api/jobs,
// GET and DELETE /api/jobs/{id}, GET /api/jobs/{id}/result.{exr,png,jpg} and
// /report.{json,csv}. Errors are JSON naming the field: 400 invalid request, 404 unknown job,
// 409 wrong state, 429 queue full.
#pragma once

#include <optional>
#include <string_view>

#include "jobs/job_queue.h"
#include "net/http_response.h"

namespace geodesic::net {

// The answer for a path under /api/jobs; nullopt for any other path.
std::optional<Response> answer_jobs(const Request& request, std::string_view path,
                                    jobs::JobQueue& queue);

}  // namespace geodesic::net
