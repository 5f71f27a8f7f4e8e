// One HTTP connection: keep-alive requests for static files, /healthz, /metrics, /api/scenes,
// /api/openapi.json and the jobs API (/api/jobs...), or the upgrade to a WebSocket at /ws; the
// token check (net/auth.h) comes first. Each request must arrive whole within the HTTP timeout
// and its body stay within kMaxMessageBytes. A job submission (its scene may hold generators to
// enumerate) is answered from the preparation pool, never on an I/O thread.
#pragma once

#include <memory>
#include <optional>

#include "net/beast.h"
#include "net/server_context.h"

namespace geodesic::net {

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket&& socket, ServerContext& context);
  void start();

 private:
  void read();
  void on_read(beast::error_code ec, std::size_t bytes);
  void prepare(http::request<http::string_body> request);
  void send(http::response<http::string_body> response);
  void on_write(bool keep_alive, beast::error_code ec, std::size_t bytes);
  void shutdown();

  ServerContext& context_;
  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  http::response<http::string_body> response_;
};

}  // namespace geodesic::net
