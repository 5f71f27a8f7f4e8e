// Test support: a real daemon on 127.0.0.1 (ephemeral port) and Beast clients whose every
// operation has a deadline, so a broken server fails a test instead of hanging it.
#pragma once

#include <chrono>
#include <functional>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "net/beast.h"
#include "net/server.h"
#include "render/service/render_service.h"

namespace geodesic::test {

namespace asio = net::asio;
namespace beast = net::beast;
namespace http = net::http;
namespace websocket = net::websocket;
using tcp = net::tcp;
using namespace std::chrono_literals;

struct DaemonOptions {
  ServiceLimits limits;
  std::chrono::milliseconds idle_timeout = std::chrono::minutes(10);
  std::chrono::milliseconds idle_eviction = std::chrono::seconds(60);
  std::chrono::milliseconds http_timeout = std::chrono::seconds(10);
  int socket_send_buffer = 0;
};

// The render service on the default device, and the server with a web directory of a few files
// in a temporary directory whose parent holds a CMakeLists.txt: a path that escaped the web
// directory would find it.
class Daemon {
 public:
  explicit Daemon(DaemonOptions options = {});
  ~Daemon();

  uint16_t port() const { return server_->port(); }
  net::Server& server() { return *server_; }
  RenderService& render() { return *render_; }
  static constexpr const char* kSecret = "outside the web directory";

 private:
  std::filesystem::path root_;
  std::unique_ptr<RenderService> render_;
  std::unique_ptr<net::Server> server_;
};

// A WebSocket client at /ws. Every text message it receives is checked against
// proto/ws-messages.schema.json (server messages), and every `frame` message must be followed
// by a binary message.
class WsClient {
 public:
  // Connects and completes the handshake. receive_buffer > 0 shrinks the socket's receive
  // buffer (a slow reader's kernel then holds little).
  explicit WsClient(uint16_t port, int receive_buffer = 0);

  struct Message {
    bool binary = false;
    std::string data;
    nlohmann::json json;  // text messages, parsed
  };
  struct Frame {
    nlohmann::json info;
    std::string jpeg;
  };

  void send(const nlohmann::json& message);
  beast::error_code send_raw(const std::string& data, bool binary = false);
  Message read(std::chrono::milliseconds timeout = 30s);
  nlohmann::json read_json(std::chrono::milliseconds timeout = 30s);  // a text message
  // Skips other messages (frames with their JPEGs) up to the next message of `type`.
  nlohmann::json read_until(const std::string& type, std::chrono::milliseconds timeout = 30s);
  // The next "scene" message: a scene's preparation (domain, renderer, pipeline) runs on a
  // worker at nice 10 (net/preparation_pool.cpp), which other tests' renders under ctest -j2
  // leave a small share of the two cores. Opening torus-lamps took 0.9 s alone and 19 s
  // beside four busy threads, so this waits longer than read_until's default.
  nlohmann::json read_scene() { return read_until("scene", std::chrono::minutes(2)); }
  Frame read_frame(std::chrono::milliseconds timeout = 30s);
  // The next frame that `accept` takes within 60 s, skipping others (earlier sizes, frames
  // already queued); throws when none comes.
  Frame read_frame_where(const std::function<bool(const nlohmann::json&)>& accept);
  // Reads until the server closes; its close code (0 when the connection ends without one).
  uint16_t read_until_close(std::chrono::milliseconds timeout = 30s);
  void close();  // a normal close (1000)

 private:
  template <typename Start>
  beast::error_code run(Start start, std::chrono::milliseconds timeout);
  Message received();  // the message in buffer_, checked

  asio::io_context io_;
  websocket::stream<beast::tcp_stream> ws_;
  beast::flat_buffer buffer_;
  bool expect_jpeg_ = false;
};

using HttpHeaders = std::vector<std::pair<http::field, std::string>>;
http::response<http::string_body> http_request(uint16_t port, http::verb method,
                                               const std::string& target,
                                               std::string body = "",
                                               const HttpHeaders& headers = {});
inline http::response<http::string_body> http_get(uint16_t port, const std::string& target) {
  return http_request(port, http::verb::get, target);
}

struct RawReply {
  std::string data;     // everything the server sent
  bool closed = false;  // the server ended the connection (rather than the timeout)
};
// Writes raw bytes, then reads until the server closes or the timeout.
RawReply raw_exchange(uint16_t port, const std::string& bytes, std::chrono::milliseconds timeout);

}  // namespace geodesic::test
