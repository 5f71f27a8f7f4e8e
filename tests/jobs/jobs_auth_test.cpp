// Bearer-token auth: with a token (here from GEODESIC_TOKEN) the API, /metrics and the WebSocket
// refuse requests without it (401) and accept it as a header or a query parameter; /healthz
// and the web client's files stay open. Without a token the daemon will not listen on a
// non-loopback address.
#include <gtest/gtest.h>

#include "job_daemon.h"

namespace geodesic::test {
namespace {

constexpr const char* kToken = "s3cret-Token_1";

// A WebSocket upgrade request to `target`; the status of the answer (101 when accepted).
unsigned upgrade(uint16_t port, const std::string& target, const HttpHeaders& extra = {}) {
  HttpHeaders headers = {{http::field::upgrade, "websocket"},
                         {http::field::connection, "Upgrade"},
                         {http::field::sec_websocket_key, "dGhlIHNhbXBsZSBub25jZQ=="},
                         {http::field::sec_websocket_version, "13"}};
  headers.insert(headers.end(), extra.begin(), extra.end());
  return http_request(port, http::verb::get, target, "", headers).result_int();
}

TEST(JobsAuth, TokenIsAcceptedAndRefused) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data", {}, {std::string("GEODESIC_TOKEN=") + kToken});
  const uint16_t port = daemon.port();

  const ApiReply missing = JobsApi(port).get("/api/jobs");
  EXPECT_EQ(missing.status, 401u);
  EXPECT_EQ(missing.json["error"], "token: missing or wrong bearer token");
  EXPECT_EQ(JobsApi(port, "wrong").get("/api/jobs").status, 401u);
  EXPECT_EQ(JobsApi(port, std::string(kToken) + "x").get("/api/jobs").status, 401u);
  EXPECT_EQ(JobsApi(port).post("/api/jobs", {{"scene", "furnace"}, {"spp", 1}}).status, 401u);
  EXPECT_EQ(JobsApi(port).get("/metrics").status, 401u);

  const JobsApi api(port, kToken);
  EXPECT_EQ(api.get("/api/jobs").status, 200u);
  EXPECT_EQ(api.get("/api/scenes").status, 200u);
  EXPECT_EQ(api.get("/metrics").status, 200u);
  EXPECT_EQ(JobsApi(port).get(std::string("/api/jobs?token=") + kToken).status, 200u);

  EXPECT_EQ(JobsApi(port).get("/healthz").status, 200u);
  EXPECT_EQ(http_get(port, "/").result(), http::status::ok);  // the page that asks for it

  EXPECT_EQ(upgrade(port, "/ws"), 401u);
  EXPECT_EQ(upgrade(port, "/ws?token=wrong"), 401u);
  EXPECT_EQ(upgrade(port, std::string("/ws?token=") + kToken), 101u);
  EXPECT_EQ(upgrade(port, "/ws", {{http::field::authorization, std::string("Bearer ") + kToken}}), 101u);
}

TEST(JobsAuth, NonLoopbackAddressNeedsAToken) {
  TempDir data;
  std::string output;
  const int code = run_cli({"serve", "--host", "0.0.0.0", "--port", "0", "--data",
                            (data.path() / "data").string()},
                           output);
  EXPECT_NE(code, 0);
  EXPECT_NE(output.find("--token: required when listening on 0.0.0.0"), std::string::npos) << output;
}

}  // namespace
}  // namespace geodesic::test
