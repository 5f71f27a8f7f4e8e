// The daemon's HTTP endpoints against a real server: health, metrics, scene list, static files,
// path traversal, request limits.
#include <gtest/gtest.h>

#include "daemon_fixture.h"

namespace geodesic::test {
namespace {

using nlohmann::json;

std::string content_type(const http::response<http::string_body>& response) {
  return std::string(response[http::field::content_type]);
}

TEST(Http, HealthzReportsDeviceAndSessions) {
  Daemon daemon;
  const auto response = http_get(daemon.port(), "/healthz");
  EXPECT_EQ(response.result(), http::status::ok);
  EXPECT_EQ(content_type(response), "application/json");
  const json body = json::parse(response.body());
  EXPECT_EQ(body["status"], "ok");
  EXPECT_FALSE(body["device"].get<std::string>().empty());
  EXPECT_EQ(body["sessions"], 0);
}

TEST(Http, MetricsNameEveryMetric) {
  Daemon daemon;
  const auto response = http_get(daemon.port(), "/metrics");
  EXPECT_EQ(response.result(), http::status::ok);
  EXPECT_TRUE(content_type(response).starts_with("text/plain"));
  for (const char* name :
       {"geodesic_sessions", "geodesic_frames_sent_total", "geodesic_samples_per_second",
        "geodesic_queue_depth", "geodesic_jpeg_encode_seconds_sum",
        "geodesic_jpeg_encode_seconds_count", "geodesic_frames_dropped_total",
        "geodesic_non_finite_samples_total", "geodesic_truncated_geodesics_total"})
    EXPECT_NE(response.body().find(std::string("\n") + name + " "), std::string::npos) << name;
}

TEST(Http, ApiScenesListsBundledScenes) {
  Daemon daemon;
  const auto response = http_get(daemon.port(), "/api/scenes");
  EXPECT_EQ(response.result(), http::status::ok);
  const json scenes = json::parse(response.body())["scenes"];
  EXPECT_NE(std::find(scenes.begin(), scenes.end(), "cornell-box"), scenes.end());
  EXPECT_NE(std::find(scenes.begin(), scenes.end(), "spherical-spheres"), scenes.end());
}

TEST(Http, ServesStaticFilesWithTheirTypes) {
  Daemon daemon;
  const auto index = http_get(daemon.port(), "/");
  EXPECT_EQ(index.result(), http::status::ok);
  EXPECT_EQ(content_type(index), "text/html; charset=utf-8");
  EXPECT_NE(index.body().find("<title>geodesic</title>"), std::string::npos);
  EXPECT_EQ(content_type(http_get(daemon.port(), "/app.js")), "text/javascript; charset=utf-8");
  EXPECT_EQ(content_type(http_get(daemon.port(), "/style.css?v=2")), "text/css; charset=utf-8");
  EXPECT_NE(http_get(daemon.port(), "/sub/").body().find("<title>sub</title>"), std::string::npos);
  EXPECT_EQ(http_get(daemon.port(), "/missing.js").result(), http::status::not_found);

  const auto head = http_request(daemon.port(), http::verb::head, "/");
  EXPECT_EQ(head.result(), http::status::ok);
  EXPECT_EQ(head[http::field::content_length], std::to_string(index.body().size()));
}

TEST(Http, PathTraversalIsNotFound) {
  Daemon daemon;
  for (const char* target : {"/../CMakeLists.txt", "/%2e%2e/CMakeLists.txt",
                             "/%2E%2E/CMakeLists.txt", "/..%2fCMakeLists.txt",
                             "/sub/../../CMakeLists.txt", "/sub/%2e%2e/%2e%2e/CMakeLists.txt"}) {
    const auto response = http_get(daemon.port(), target);
    EXPECT_EQ(response.result(), http::status::not_found) << target;
    EXPECT_EQ(response.body().find(Daemon::kSecret), std::string::npos) << target;
  }
}

TEST(Http, OnlyGetAndHead) {
  Daemon daemon;
  const auto response = http_request(daemon.port(), http::verb::post, "/healthz", "{}");
  EXPECT_EQ(response.result(), http::status::method_not_allowed);
  EXPECT_EQ(response[http::field::allow], "GET, HEAD");
}

TEST(Http, BodyOverTheLimitIs413) {
  Daemon daemon;
  const auto reply = raw_exchange(daemon.port(),
                                  "POST /healthz HTTP/1.1\r\nHost: x\r\nContent-Length: 2097152\r\n\r\n",
                                  10s);
  EXPECT_TRUE(reply.data.starts_with("HTTP/1.1 413")) << reply.data;
  EXPECT_TRUE(reply.closed);
}

TEST(Http, SlowRequestIsCutAtTheTimeout) {
  DaemonOptions options;
  options.http_timeout = 1s;
  Daemon daemon(options);
  const auto start = std::chrono::steady_clock::now();
  // Half a request header, then nothing: the server must not wait for the rest forever.
  const auto reply = raw_exchange(daemon.port(), "GET / HTTP/1.1\r\nHost: x\r\n", 10s);
  EXPECT_TRUE(reply.closed);
  EXPECT_TRUE(reply.data.empty()) << reply.data;
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
}

TEST(Http, WebSocketUpgradeOnlyAtWs) {
  Daemon daemon;
  const auto reply = raw_exchange(daemon.port(),
                                  "GET /socket HTTP/1.1\r\nHost: x\r\nConnection: Upgrade\r\n"
                                  "Upgrade: websocket\r\nSec-WebSocket-Version: 13\r\n"
                                  "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n",
                                  2s);  // the connection stays open for the next request
  EXPECT_TRUE(reply.data.starts_with("HTTP/1.1 404")) << reply.data;
}

}  // namespace
}  // namespace geodesic::test
