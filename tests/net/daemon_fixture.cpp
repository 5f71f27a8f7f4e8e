#include "daemon_fixture.h"

#include <array>
#include <fstream>
#include <functional>
#include <optional>
#include <stdexcept>
#include <system_error>

#include <gtest/gtest.h>
#include <stdlib.h>

#include "schema_check.h"

namespace geodesic::test {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

tcp::endpoint local(uint16_t port) { return {asio::ip::make_address("127.0.0.1"), port}; }

std::chrono::milliseconds left_until(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  if (left <= 0ms) throw std::runtime_error("timed out waiting for the server");
  return left;
}

}  // namespace

Daemon::Daemon(DaemonOptions options) {
  std::string dir = (fs::temp_directory_path() / "geodesic-net-XXXXXX").string();
  if (!mkdtemp(dir.data())) throw std::runtime_error("mkdtemp failed");
  root_ = dir;
  write_file(root_ / "CMakeLists.txt", kSecret);
  fs::create_directories(root_ / "web" / "sub");
  write_file(root_ / "web" / "index.html", "<!doctype html><title>geodesic</title>\n");
  write_file(root_ / "web" / "app.js", "export const answer = 42;\n");
  write_file(root_ / "web" / "style.css", "body { margin: 0; }\n");
  write_file(root_ / "web" / "sub" / "index.html", "<!doctype html><title>sub</title>\n");

  render_ = std::make_unique<RenderService>("", GEODESIC_SOURCE_DIR "/scenes", options.limits);
  net::ServerOptions server_options;
  server_options.port = 0;
  server_options.web_dir = root_ / "web";
  server_options.idle_timeout = options.idle_timeout;
  server_options.idle_eviction = options.idle_eviction;
  server_options.http_timeout = options.http_timeout;
  server_options.socket_send_buffer = options.socket_send_buffer;
  server_ = std::make_unique<net::Server>(*render_, server_options);
}

Daemon::~Daemon() {
  server_.reset();
  render_.reset();
  std::error_code ignored;
  fs::remove_all(root_, ignored);
}

WsClient::WsClient(uint16_t port, int receive_buffer) : ws_(io_) {
  auto& stream = beast::get_lowest_layer(ws_);
  if (receive_buffer > 0) {
    stream.socket().open(tcp::v4());
    stream.socket().set_option(asio::socket_base::receive_buffer_size(receive_buffer));
  }
  if (auto ec = run([&](auto handler) { stream.async_connect(local(port), handler); }, 10s))
    throw std::runtime_error("connect: " + ec.message());
  if (auto ec = run([&](auto handler) { ws_.async_handshake("127.0.0.1", "/ws", handler); }, 10s))
    throw std::runtime_error("WebSocket handshake: " + ec.message());
}

// Runs one asynchronous operation to completion; the stream's deadline bounds it.
template <typename Start>
beast::error_code WsClient::run(Start start, std::chrono::milliseconds timeout) {
  std::optional<beast::error_code> result;
  beast::get_lowest_layer(ws_).expires_after(timeout);
  start([&result](beast::error_code ec, auto&&...) { result = ec; });
  io_.restart();
  io_.run();
  return result.value_or(beast::error::timeout);
}

void WsClient::send(const nlohmann::json& message) {
  if (auto ec = send_raw(message.dump())) throw std::runtime_error("send: " + ec.message());
}

beast::error_code WsClient::send_raw(const std::string& data, bool binary) {
  ws_.binary(binary);
  return run([&](auto handler) { ws_.async_write(asio::buffer(data), handler); }, 30s);
}

WsClient::Message WsClient::received() {
  Message message{ws_.got_binary(), beast::buffers_to_string(buffer_.data()), {}};
  if (message.binary != expect_jpeg_)
    ADD_FAILURE() << (message.binary ? "a binary message without its frame message"
                                     : "a frame message not followed by its JPEG");
  expect_jpeg_ = false;
  if (!message.binary) {
    message.json = nlohmann::json::parse(message.data);
    for (const auto& error : ws_messages_schema().errors(message.json, "/$defs/server_message"))
      ADD_FAILURE() << "schema: " << error << "\n  in " << message.data;
    expect_jpeg_ = message.json.value("type", "") == "frame";
  }
  return message;
}

WsClient::Message WsClient::read(std::chrono::milliseconds timeout) {
  buffer_.clear();
  if (auto ec = run([&](auto handler) { ws_.async_read(buffer_, handler); }, timeout))
    throw std::runtime_error("WebSocket read: " + ec.message());
  return received();
}

nlohmann::json WsClient::read_json(std::chrono::milliseconds timeout) {
  Message message = read(timeout);
  if (message.binary) throw std::runtime_error("expected a text message, got a binary one");
  return message.json;
}

nlohmann::json WsClient::read_until(const std::string& type, std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    Message message = read(left_until(deadline));
    if (!message.binary && message.json["type"] == type) return message.json;
  }
}

WsClient::Frame WsClient::read_frame(std::chrono::milliseconds timeout) {
  const nlohmann::json info = read_until("frame", timeout);
  Message jpeg = read(timeout);
  if (!jpeg.binary) throw std::runtime_error("frame message not followed by a binary message");
  return {info, std::move(jpeg.data)};
}

WsClient::Frame WsClient::read_frame_where(const std::function<bool(const nlohmann::json&)>& accept) {
  const auto deadline = Clock::now() + 60s;
  while (Clock::now() < deadline) {
    Frame frame = read_frame();
    if (accept(frame.info)) return frame;
  }
  throw std::runtime_error("no frame as expected within 60 s");
}

uint16_t WsClient::read_until_close(std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    buffer_.clear();
    const auto ec = run([&](auto handler) { ws_.async_read(buffer_, handler); },
                        left_until(deadline));
    if (ec == websocket::error::closed) return ws_.reason().code;
    if (ec == beast::error::timeout) throw std::runtime_error("timed out waiting for a close");
    if (ec) return 0;
    received();
  }
}

void WsClient::close() {
  if (auto ec = run([&](auto handler) { ws_.async_close(websocket::close_code::normal, handler); },
                    10s))
    throw std::runtime_error("WebSocket close: " + ec.message());
}

http::response<http::string_body> http_request(uint16_t port, http::verb method,
                                               const std::string& target, std::string body,
                                               const HttpHeaders& headers) {
  asio::io_context io;
  beast::tcp_stream stream(io);
  stream.expires_after(10s);
  http::request<http::string_body> request(method, target, 11);
  request.set(http::field::host, "127.0.0.1");
  for (const auto& [field, value] : headers) request.set(field, value);
  if (!body.empty()) {
    request.body() = std::move(body);
    request.prepare_payload();
  }
  http::response_parser<http::string_body> parser;
  parser.body_limit(64 << 20);  // job results (EXR) are larger than Beast's default 8 MiB
  parser.skip(method == http::verb::head);  // a HEAD answer has a length but no body
  beast::flat_buffer buffer;
  beast::error_code result;
  stream.async_connect(local(port), [&](beast::error_code ec) {
    if (ec) return void(result = ec);
    http::async_write(stream, request, [&](beast::error_code ec, size_t) {
      if (ec) return void(result = ec);
      http::async_read(stream, buffer, parser,
                       [&](beast::error_code ec, size_t) { result = ec; });
    });
  });
  io.run();
  if (result) throw std::runtime_error("HTTP " + target + ": " + result.message());
  return parser.release();
}

RawReply raw_exchange(uint16_t port, const std::string& bytes, std::chrono::milliseconds timeout) {
  asio::io_context io;
  beast::tcp_stream stream(io);
  stream.expires_after(timeout);
  RawReply reply;
  std::array<char, 4096> chunk;
  std::function<void(beast::error_code, size_t)> on_read = [&](beast::error_code ec, size_t n) {
    reply.data.append(chunk.data(), n);
    if (ec) {
      reply.closed = ec == asio::error::eof || ec == asio::error::connection_reset;
      return;
    }
    stream.async_read_some(asio::buffer(chunk), on_read);
  };
  stream.async_connect(local(port), [&](beast::error_code ec) {
    if (ec) return;
    asio::async_write(stream, asio::buffer(bytes), [&](beast::error_code ec, size_t) {
      if (!ec) stream.async_read_some(asio::buffer(chunk), on_read);
    });
  });
  io.run();
  return reply;
}

}  // namespace geodesic::test
