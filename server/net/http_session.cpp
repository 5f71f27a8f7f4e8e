#include "net/http_session.h"

#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "net/job_routes.h"
#include "net/auth.h"
#include "net/http_response.h"
#include "net/metrics.h"
#include "net/openapi.h"
#include "net/preparation_pool.h"
#include "net/static_files.h"
#include "net/websocket_session.h"

namespace geodesic::net {
namespace {

Response unauthorized(const Request& request) {
  Response response = json_error(request, http::status::unauthorized,
                                 "token: missing or wrong bearer token");
  response.set(http::field::www_authenticate, "Bearer");
  return response;
}

Response error_response(const Request& request, http::status status, std::string_view text) {
  return make_response(request, status, "text/plain; charset=utf-8", std::string(text) + "\n");
}

std::string_view path_of(const Request& request) {
  const std::string_view target(request.target().data(), request.target().size());
  return target.substr(0, target.find('?'));
}

// Whole answers, HEAD bodies dropped and exceptions answered 500 JSON.
Response respond(const Request& request, ServerContext& context);

// Requests whose answer may enumerate a group or load meshes: POST /api/jobs.
bool needs_preparation(const Request& request) {
  const std::string_view path = path_of(request);
  return request.method() == http::verb::post && (path == "/api/jobs" || path == "/api/jobs/");
}

Response answer(const Request& request, ServerContext& context) {
  const std::string_view path = path_of(request);
  if (needs_token(path) && !authorized(request, context.options.token))
    return unauthorized(request);
  if (context.jobs)
    if (auto response = answer_jobs(request, path, *context.jobs)) return std::move(*response);
  if (request.method() != http::verb::get && request.method() != http::verb::head) {
    Response response = error_response(request, http::status::method_not_allowed,
                                       "only GET and HEAD");
    response.set(http::field::allow, "GET, HEAD");
    return response;
  }
  if (path == "/healthz") {
    const ServiceStats stats = context.render.stats();
    return json_response(request,
                         {{"status", "ok"}, {"device", stats.device}, {"sessions", stats.sessions}});
  }
  if (path == "/metrics")
    return make_response(request, http::status::ok, "text/plain; version=0.0.4; charset=utf-8",
                         prometheus_metrics(context.render.stats(), context.counters));
  if (path == "/api/openapi.json")
    return make_response(request, http::status::ok, "application/json",
                         std::string(openapi_document()));
  if (path == "/api/scenes")
    return json_response(request, {{"scenes", context.render.bundled_scenes()}});
  auto file = load_static_file(context.options.web_dir, path);
  if (!file) return error_response(request, http::status::not_found, "not found");
  return make_response(request, http::status::ok, file->mime_type, std::move(file->body));
}

Response respond(const Request& request, ServerContext& context) {
  Response response;
  try {
    response = answer(request, context);
  } catch (const std::exception& e) {
    response = json_error(request, http::status::internal_server_error,
                          std::string("server: ") + e.what());
  }
  if (request.method() == http::verb::head) response.body().clear();  // headers keep the length
  return response;
}

}  // namespace

HttpSession::HttpSession(tcp::socket&& socket, ServerContext& context)
    : context_(context), stream_(std::move(socket)) {}

void HttpSession::start() {
  asio::dispatch(stream_.get_executor(),
                 beast::bind_front_handler(&HttpSession::read, shared_from_this()));
}

void HttpSession::read() {
  parser_.emplace();
  parser_->body_limit(kMaxMessageBytes);
  // One deadline for the whole request: a client trickling bytes cannot keep the connection.
  stream_.expires_after(context_.options.http_timeout);
  http::async_read(stream_, buffer_, *parser_,
                   beast::bind_front_handler(&HttpSession::on_read, shared_from_this()));
}

void HttpSession::on_read(beast::error_code ec, std::size_t) {
  if (ec == http::error::end_of_stream) return shutdown();
  if (ec == http::error::body_limit) {
    Request head;  // answer as HTTP/1.1, then close
    head.keep_alive(false);
    return send(json_error(head, http::status::payload_too_large,
                           "body: larger than " + std::to_string(kMaxMessageBytes) + " bytes"));
  }
  // Not HTTP (a NUL in the target, a malformed header): say so, then close. A timeout, a
  // reset or a request cut short gets nothing: there is no one to answer.
  if (ec.category() == http::make_error_code(http::error::bad_target).category() &&
      ec != http::error::partial_message) {
    Request head;
    head.keep_alive(false);
    return send(error_response(head, http::status::bad_request, "bad request: " + ec.message()));
  }
  if (ec) return;

  Request request = parser_->release();
  if (websocket::is_upgrade(request)) {
    if (path_of(request) != "/ws")
      return send(error_response(request, http::status::not_found, "WebSocket only at /ws"));
    if (!authorized(request, context_.options.token)) return send(unauthorized(request));
    std::make_shared<WebSocketSession>(stream_.release_socket(), context_)
        ->start(std::move(request));
    return;
  }
  // Only authorized submissions take a place on the pool (a refusal is answered here at once).
  if (context_.preparation && needs_preparation(request) &&
      authorized(request, context_.options.token))
    return prepare(std::move(request));
  send(respond(request, context_));
}

// Answers on the preparation pool, then writes on this connection's strand; a full pool answers
// 503 at once.
void HttpSession::prepare(http::request<http::string_body> request) {
  auto shared = std::make_shared<Request>(std::move(request));
  const bool queued = context_.preparation->submit([self = shared_from_this(), shared] {
    auto response = std::make_shared<Response>(respond(*shared, self->context_));
    asio::post(self->stream_.get_executor(), [self, response] { self->send(std::move(*response)); });
  });
  if (queued) return;
  Response busy = json_error(*shared, http::status::service_unavailable,
                             "body: the server is busy preparing other scenes; try again shortly");
  busy.set(http::field::retry_after, "1");
  send(std::move(busy));
}

void HttpSession::send(http::response<http::string_body> response) {
  response_ = std::move(response);
  const bool keep_alive = response_.keep_alive();
  stream_.expires_after(context_.options.http_timeout);
  http::async_write(stream_, response_,
                    beast::bind_front_handler(&HttpSession::on_write, shared_from_this(),
                                              keep_alive));
}

void HttpSession::on_write(bool keep_alive, beast::error_code ec, std::size_t) {
  if (ec) return;
  if (!keep_alive) return shutdown();
  read();
}

void HttpSession::shutdown() {
  beast::error_code ignored;
  stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
}

}  // namespace geodesic::net
