#include "job_daemon.h"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../net/schema_check.h"

namespace geodesic::test {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// fork + exec of the CLI with stdout and stderr to `log`; the child's pid.
pid_t spawn(const std::vector<std::string>& args, const std::vector<std::string>& env,
            const fs::path& log) {
  std::vector<std::string> argv_text = {GEODESIC_CLI};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    for (const std::string& e : env) putenv(strdup(e.c_str()));
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

// Each daemon its own log: a restarted one must not be read for its predecessor's port.
int next_log_number() {
  static std::atomic<int> number{0};
  return ++number;
}

}  // namespace

TempDir::TempDir() {
  std::string dir = (fs::temp_directory_path() / "geodesic-jobs-XXXXXX").string();
  if (!mkdtemp(dir.data())) throw std::runtime_error("mkdtemp failed");
  path_ = dir;
}

TempDir::~TempDir() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

DaemonProcess::DaemonProcess(const fs::path& data_dir, const std::vector<std::string>& args,
                             const std::vector<std::string>& env)
    : log_(data_dir.parent_path() / ("daemon-" + std::to_string(next_log_number()) + ".log")) {
  std::vector<std::string> all = {"serve", "--host", "127.0.0.1", "--port", "0",
                                  "--data", data_dir.string()};
  all.insert(all.end(), args.begin(), args.end());
  pid_ = spawn(all, env, log_);
  // The daemon prints "serving http://127.0.0.1:<port>/" once it listens.
  const auto deadline = Clock::now() + std::chrono::seconds(120);
  while (Clock::now() < deadline) {
    const std::string text = read_file(log_);
    const size_t at = text.find("serving http://127.0.0.1:");
    if (at != std::string::npos) {
      port_ = uint16_t(std::stoi(text.substr(at + 25)));
      return;
    }
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      throw std::runtime_error("the daemon exited before listening:\n" + text);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(SIGKILL);
  throw std::runtime_error("the daemon did not listen within 120 s:\n" + read_file(log_));
}

DaemonProcess::~DaemonProcess() {
  if (pid_ < 0) return;
  ::kill(pid_, SIGTERM);
  for (int i = 0; i < 600; ++i) {
    if (waitpid(pid_, nullptr, WNOHANG) == pid_) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(SIGKILL);
}

int DaemonProcess::kill(int signal) {
  if (pid_ < 0) throw std::logic_error("the daemon has already ended");
  ::kill(pid_, signal);
  int status = 0;
  waitpid(pid_, &status, 0);
  pid_ = -1;
  return status;
}

std::string DaemonProcess::log() const { return read_file(log_); }

int run_cli(const std::vector<std::string>& args, std::string& output) {
  TempDir dir;
  const fs::path log = dir.path() / "cli.log";
  const pid_t pid = spawn(args, {}, log);
  int status = 0;
  waitpid(pid, &status, 0);
  output = read_file(log);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

ApiReply JobsApi::request(http::verb method, const std::string& target,
                          const std::string& body) const {
  HttpHeaders headers;
  if (!token_.empty()) headers.emplace_back(http::field::authorization, "Bearer " + token_);
  if (!body.empty()) headers.emplace_back(http::field::content_type, "application/json");
  const auto response = http_request(port_, method, target, body, headers);
  ApiReply reply{response.result_int(), nullptr, response.body(),
                 std::string(response[http::field::content_type])};
  if (reply.content_type == "application/json") reply.json = nlohmann::json::parse(reply.body);
  if (reply.status >= 400 && reply.status != 413) {  // every API error names its field
    for (const auto& error : openapi_errors(reply.json, "Error"))
      ADD_FAILURE() << target << ": " << error << "\n  in " << reply.body;
  }
  return reply;
}

int64_t JobsApi::submit(const nlohmann::json& body) const {
  const ApiReply reply = post("/api/jobs", body);
  if (reply.status != 202) throw std::runtime_error("submit: " + std::to_string(reply.status) + " " + reply.body);
  for (const auto& error : openapi_errors(reply.json, "JobAccepted")) ADD_FAILURE() << error;
  return reply.json["id"].get<int64_t>();
}

nlohmann::json JobsApi::wait_for(int64_t id, const std::function<bool(const nlohmann::json&)>& done,
                                 std::chrono::seconds timeout) const {
  const auto deadline = Clock::now() + timeout;
  nlohmann::json status;
  while (Clock::now() < deadline) {
    const ApiReply reply = get("/api/jobs/" + std::to_string(id));
    if (reply.status != 200) throw std::runtime_error("status: " + reply.body);
    for (const auto& error : openapi_errors(reply.json, "JobStatus")) ADD_FAILURE() << error;
    status = reply.json;
    if (done(status)) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  throw std::runtime_error("timed out waiting for job " + std::to_string(id) + "; last status " +
                           status.dump());
}

std::vector<std::string> openapi_errors(const nlohmann::json& value, const std::string& name) {
  static const SchemaCheck openapi(GEODESIC_SOURCE_DIR "/proto/openapi.json");
  return openapi.errors(value, "/components/schemas/" + name);
}

}  // namespace geodesic::test
