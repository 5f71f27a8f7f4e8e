// Test support for render jobs: a real `geodesic serve` process (so it can be killed with
// SIGKILL and started again on the same data directory) and a small client of its jobs API
// whose answers are checked against proto/openapi.json.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <sys/types.h>

#include "../net/daemon_fixture.h"

namespace geodesic::test {

// A temporary directory, removed with everything in it.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

class DaemonProcess {
 public:
  // Starts the CLI's `serve` on 127.0.0.1 (ephemeral port) with --data data_dir and `args`,
  // `env` ("NAME=value") added to its environment; waits for it to listen (up to 120 s).
  DaemonProcess(const std::filesystem::path& data_dir, const std::vector<std::string>& args = {},
                const std::vector<std::string>& env = {});
  ~DaemonProcess();  // SIGTERM, then SIGKILL if it has not ended within 30 s
  DaemonProcess(const DaemonProcess&) = delete;
  DaemonProcess& operator=(const DaemonProcess&) = delete;

  uint16_t port() const { return port_; }
  pid_t pid() const { return pid_; }  // -1 once ended
  // Sends `signal` and waits for the process to end; its wait status.
  int kill(int signal);
  std::string log() const;

 private:
  pid_t pid_ = -1;
  uint16_t port_ = 0;
  std::filesystem::path log_;
};

// Runs the CLI with `args` to its end (for options refused before it starts serving); returns
// its exit code and fills `output` with what it printed.
int run_cli(const std::vector<std::string>& args, std::string& output);

struct ApiReply {
  unsigned status = 0;
  nlohmann::json json;  // null unless the body is JSON
  std::string body;
  std::string content_type;
};

class JobsApi {
 public:
  explicit JobsApi(uint16_t port, std::string token = "") : port_(port), token_(std::move(token)) {}
  ApiReply request(http::verb method, const std::string& target, const std::string& body = "") const;
  ApiReply get(const std::string& target) const { return request(http::verb::get, target); }
  ApiReply post(const std::string& target, const nlohmann::json& body) const {
    return request(http::verb::post, target, body.dump());
  }
  // Submits and expects 202; the job id.
  int64_t submit(const nlohmann::json& body) const;
  // Polls GET /api/jobs/{id} until `done(status)` or the timeout (then fails the test).
  nlohmann::json wait_for(int64_t id, const std::function<bool(const nlohmann::json&)>& done,
                          std::chrono::seconds timeout = std::chrono::seconds(120)) const;

 private:
  uint16_t port_;
  std::string token_;
};

// Whether a job's status is final (done, failed or cancelled).
inline bool job_ended(const nlohmann::json& status) {
  return status["state"] != "queued" && status["state"] != "running";
}

// What is wrong with `value` against proto/openapi.json's components/schemas/<name>.
std::vector<std::string> openapi_errors(const nlohmann::json& value, const std::string& name);

}  // namespace geodesic::test
