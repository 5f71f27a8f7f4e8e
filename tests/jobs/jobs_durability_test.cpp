// Jobs survive a killed daemon: SIGKILL in the middle of a running job, start again on the same
// data directory, and every accepted job is still there, a finished job's files are the same
// bytes, and the running job resumes from its checkpoint (its sample count goes on, not from 0)
// and completes. A SIGTERM checkpoints the running job as it stops; a result that does not fit
// (under a file-size limit, or on a full tmpfs) fails its job with the reason and touches
// nothing else; a lost Vulkan device makes the job start over from its checkpoint, an
// out-of-device-memory error fails it.
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/resource.h>

#include "job_daemon.h"
#include "render/prepare/image_io.h"

namespace geodesic::test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// The mean of every channel of every pixel: the furnace's radiance is 2.0.
double mean_value(const fs::path& file) {
  const Image image = read_image(file);
  double sum = 0;
  for (float v : image.rgb) sum += v;
  return sum / double(image.rgb.size());
}

// Long enough to be interrupted on any machine: seconds of furnace paths.
constexpr int kLongSpp = 1500;
const json kLongJob = {{"scene", "furnace"}, {"width", 64}, {"height", 48}, {"spp", kLongSpp},
                       {"formats", {"exr", "png"}}};
const json kShortJob = {{"scene", "furnace"}, {"width", 32}, {"height", 24}, {"spp", 8},
                        {"formats", {"png"}}};

TEST(JobsDurability, SigkillThenRestartResumesFromTheCheckpoint) {
  TempDir data;
  const fs::path dir = data.path() / "data";
  const std::vector<std::string> args = {"--max-jobs", "1", "--checkpoint-seconds", "1"};

  int64_t finished = 0, interrupted = 0, waiting = 0;
  std::string finished_png;
  json at_kill;
  {
    DaemonProcess daemon(dir, args);
    const JobsApi api(daemon.port());
    finished = api.submit(kShortJob);
    ASSERT_EQ(api.wait_for(finished, job_ended, std::chrono::seconds(240))["state"], "done");
    finished_png = file_bytes(dir / "jobs" / std::to_string(finished) / "result.png");
    ASSERT_FALSE(finished_png.empty());

    interrupted = api.submit(kLongJob);
    waiting = api.submit(kShortJob);  // queued behind it (--max-jobs 1)
    at_kill = api.wait_for(interrupted, [](const json& s) {
      return s["checkpoint_samples"].get<int>() > 0 || job_ended(s);
    });
    ASSERT_EQ(at_kill["state"], "running") << "finished before it could be killed: " << at_kill.dump();
    const int status = daemon.kill(SIGKILL);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  }

  DaemonProcess daemon(dir, args);
  const JobsApi api(daemon.port());
  const json jobs = api.get("/api/jobs").json["jobs"];
  ASSERT_EQ(jobs.size(), 3u);  // no job lost
  EXPECT_EQ(jobs[0]["state"], "done");
  EXPECT_EQ(file_bytes(dir / "jobs" / std::to_string(finished) / "result.png"), finished_png);

  // From the checkpoint on: never back to 0, never below what the checkpoint held.
  const uint32_t checkpoint = at_kill["checkpoint_samples"].get<uint32_t>();
  const json resumed = api.wait_for(interrupted, [](const json& s) { return s["state"] != "queued"; });
  EXPECT_GE(resumed["samples"].get<uint32_t>(), checkpoint) << resumed.dump();
  const json done = api.wait_for(interrupted, job_ended, std::chrono::seconds(240));
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_EQ(done["samples"], kLongSpp);
  // Elapsed time goes on from the checkpoint's too (taken at most a second and a pass before).
  EXPECT_GT(done["elapsed"].get<double>(), at_kill["elapsed"].get<double>() - 1.5);
  uint32_t previous = 0;
  for (const json& point : done["series"]) {  // the series goes on across the restart
    EXPECT_GE(point["spp"].get<uint32_t>(), previous);
    previous = point["spp"].get<uint32_t>();
  }
  EXPECT_EQ(previous, uint32_t(kLongSpp));

  const Image image = read_image(dir / "jobs" / std::to_string(interrupted) / "result.exr");
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
  EXPECT_NEAR(mean_value(dir / "jobs" / std::to_string(interrupted) / "result.exr"), 2.0, 0.1);
  EXPECT_FALSE(fs::exists(dir / "jobs" / std::to_string(interrupted) / "checkpoint.bin"));

  EXPECT_EQ(api.wait_for(waiting, job_ended)["state"], "done");
}

TEST(JobsDurability, SigtermCheckpointsTheRunningJobWhichResumesAfterRestart) {
  TempDir data;
  const fs::path dir = data.path() / "data";
  // No periodic checkpoint: the only one is the shutdown's.
  const std::vector<std::string> args = {"--max-jobs", "1", "--checkpoint-seconds", "86400"};
  int64_t id = 0;
  json at_term;
  {
    DaemonProcess daemon(dir, args);
    const JobsApi api(daemon.port());
    id = api.submit(kLongJob);
    at_term = api.wait_for(id, [](const json& s) { return s["samples"].get<int>() >= 16 || job_ended(s); });
    ASSERT_EQ(at_term["state"], "running") << at_term.dump();
    const auto signalled = std::chrono::steady_clock::now();
    const int status = daemon.kill(SIGTERM);
    std::printf("SIGTERM to exit: %.2f s\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "wait status " << status;
  }
  ASSERT_TRUE(fs::exists(dir / "jobs" / std::to_string(id) / "checkpoint.bin"));

  DaemonProcess daemon(dir, args);
  const JobsApi api(daemon.port());
  // The checkpoint holds at least every sample rendered when the signal came.
  const json resumed = api.wait_for(id, [](const json& s) { return s["state"] != "queued"; });
  EXPECT_GE(resumed["checkpoint_samples"].get<int>(), at_term["samples"].get<int>()) << resumed.dump();
  EXPECT_GE(resumed["samples"].get<int>(), at_term["samples"].get<int>()) << resumed.dump();
  const json done = api.wait_for(id, job_ended, std::chrono::seconds(240));
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_EQ(done["samples"], kLongSpp);
  EXPECT_GE(done["elapsed"].get<double>(), at_term["elapsed"].get<double>());
  EXPECT_NEAR(mean_value(dir / "jobs" / std::to_string(id) / "result.exr"), 2.0, 0.1);
}

TEST(JobsDurability, AResultTooLargeForTheDiskFailsItsJobAndNothingElse) {
  TempDir data;
  const fs::path dir = data.path() / "data";
  DaemonProcess daemon(dir, {"--max-jobs", "1", "--checkpoint-seconds", "86400"});
  const JobsApi api(daemon.port());
  const int64_t before = api.submit(kShortJob);
  ASSERT_EQ(api.wait_for(before, job_ended)["state"], "done");
  const fs::path kept = dir / "jobs" / std::to_string(before) / "result.png";
  const std::string kept_bytes = file_bytes(kept);

  // A full disk, for real and unprivileged: the daemon's file-size limit (RLIMIT_FSIZE) goes
  // down to 1 MiB, less than a full-HD result, while the job renders, and back up once it has
  // failed (the disk freed). Only meanwhile: lavapipe's device memory is a memfd that grows
  // with every allocation, and its growth past the limit is a SIGBUS (docs/reliability.md).
  // Both writers (OpenEXR, and libpng into memory then one checked write) report the short
  // write; the read-back would catch one that did not.
  auto file_size_limit = [&](rlim_t bytes) {  // the soft limit: it can go up again
    rlimit limit{};
    ASSERT_EQ(prlimit(daemon.pid(), RLIMIT_FSIZE, nullptr, &limit), 0);
    limit.rlim_cur = bytes;
    ASSERT_EQ(prlimit(daemon.pid(), RLIMIT_FSIZE, &limit, nullptr), 0);
  };
  for (const char* format : {"exr", "png"}) {
    const int64_t id = api.submit({{"scene", "cornell-box"}, {"width", 1920}, {"height", 1080},
                                   {"spp", 3}, {"formats", {format}}});
    const json started = api.wait_for(id, [](const json& s) { return s["samples"].get<int>() >= 1 || job_ended(s); });
    ASSERT_EQ(started["state"], "running") << started.dump();
    file_size_limit(1 << 20);
    const json failed = api.wait_for(id, job_ended, std::chrono::seconds(240));
    file_size_limit(RLIM_INFINITY);
    EXPECT_EQ(failed["state"], "failed") << failed.dump();
    const std::string message = failed["message"];
    std::printf("%s result: %s\n", format, message.c_str());
    EXPECT_EQ(message.find(dir.string()), std::string::npos) << "a server path: " << message;
    EXPECT_NE(message.find(std::string("result.") + format + ": File too large"), std::string::npos)
        << message;
    EXPECT_FALSE(fs::exists(dir / "jobs" / std::to_string(id))) << "a failed job leaves no files";
  }
  EXPECT_EQ(api.wait_for(api.submit(kShortJob), job_ended)["state"], "done");  // the store goes on
  EXPECT_EQ(file_bytes(kept), kept_bytes);
  EXPECT_EQ(api.get("/api/jobs").json["jobs"].size(), 4u);
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
}

// A full disk for real: a 3 MiB tmpfs as the data directory (mounting one needs root; the test
// is skipped without). A 1920x1080 EXR result (about 25 MB) does not fit: its job fails naming
// ENOSPC, and the jobs before and after it are done. Then a file fills the disk: a submission
// is answered 503 JSON with Retry-After (the store could not write it), the stored jobs stay
// listed, and once space is back a submission is stored and done.
TEST(JobsDurability, AFullDiskFailsTheJobWhoseResultDoesNotFitAndRefusesSubmissionsWith503) {
  TempDir data;
  const fs::path disk = data.path() / "disk";
  fs::create_directories(disk);
  if (mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=3m") != 0)
    GTEST_SKIP() << "mounting a tmpfs: " << std::strerror(errno);
  struct Unmount {  // after the daemon, declared below, has ended
    const fs::path& disk;
    ~Unmount() { umount2(disk.c_str(), MNT_DETACH); }
  } unmount{disk};
  const fs::path dir = disk / "data";
  DaemonProcess daemon(dir, {"--max-jobs", "1"});
  const JobsApi api(daemon.port());
  const int64_t before = api.submit(kShortJob);
  const int64_t full = api.submit({{"scene", "cornell-box"}, {"width", 1920}, {"height", 1080},
                                   {"spp", 1}, {"formats", {"exr"}}});
  const int64_t after = api.submit(kShortJob);
  EXPECT_EQ(api.wait_for(before, job_ended)["state"], "done");
  const json failed = api.wait_for(full, job_ended, std::chrono::seconds(240));
  EXPECT_EQ(failed["state"], "failed") << failed.dump();
  const std::string message = failed["message"];
  std::printf("full disk: %s\n", message.c_str());
  EXPECT_NE(message.find("result.exr: No space left on device"), std::string::npos) << message;
  EXPECT_EQ(message.find(dir.string()), std::string::npos) << "a server path: " << message;
  EXPECT_EQ(api.wait_for(after, job_ended)["state"], "done");
  EXPECT_TRUE(fs::exists(dir / "jobs" / std::to_string(before) / "result.png"));
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();

  const fs::path filler = disk / "filler";
  {
    std::ofstream fill(filler, std::ios::binary);
    const std::string block(64 * 1024, '\0');
    while (fill.write(block.data(), block.size())) {}
  }
  const auto refused = http_request(daemon.port(), http::verb::post, "/api/jobs", kShortJob.dump());
  EXPECT_EQ(refused.result_int(), 503u) << refused.body();
  EXPECT_EQ(refused[http::field::content_type], "application/json");
  EXPECT_EQ(refused[http::field::retry_after], "60");
  const std::string error = json::parse(refused.body()).value("error", "");
  EXPECT_TRUE(error.starts_with("store: the job was not stored: ")) << error;
  EXPECT_EQ(error.find(dir.string()), std::string::npos) << "a server path: " << error;
  std::printf("full disk, POST: %u %s\n", refused.result_int(), error.c_str());
  EXPECT_EQ(api.get("/api/jobs").json["jobs"].size(), 3u);
  fs::remove(filler);
  EXPECT_EQ(api.wait_for(api.submit(kShortJob), job_ended)["state"], "done");
}

// GEODESIC_FAULT makes the daemon's 60th queue submission fail as a driver would; with no
// session open they are all the job's, a few seconds into it.
TEST(JobsDurability, ALostDeviceMakesTheJobStartOverFromItsCheckpoint) {
  TempDir data;
  const fs::path dir = data.path() / "data";
  DaemonProcess daemon(dir, {"--checkpoint-seconds", "1"}, {"GEODESIC_FAULT=device-lost@60"});
  const JobsApi api(daemon.port());
  const int64_t id = api.submit(kLongJob);
  const json done = api.wait_for(id, job_ended, std::chrono::seconds(240));
  ASSERT_EQ(done["state"], "done") << done.dump() << "\n" << daemon.log();
  EXPECT_EQ(done["samples"], kLongSpp);
  EXPECT_NEAR(mean_value(dir / "jobs" / std::to_string(id) / "result.exr"), 2.0, 0.1);
  const std::string log = daemon.log();
  EXPECT_NE(log.find("(VK_ERROR_DEVICE_LOST); starting over from its checkpoint"), std::string::npos) << log;
  EXPECT_NE(log.find("rendering on a new"), std::string::npos) << log;
  EXPECT_EQ(api.wait_for(api.submit(kShortJob), job_ended)["state"], "done");
}

TEST(JobsDurability, OutOfDeviceMemoryFailsTheJobWithTheReason) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data", {}, {"GEODESIC_FAULT=oom@60"});
  const JobsApi api(daemon.port());
  const json failed = api.wait_for(api.submit(kLongJob), job_ended, std::chrono::seconds(240));
  EXPECT_EQ(failed["state"], "failed") << failed.dump();
  EXPECT_NE(failed["message"].get<std::string>().find("VK_ERROR_OUT_OF_DEVICE_MEMORY"),
            std::string::npos) << failed.dump();
  EXPECT_EQ(api.wait_for(api.submit(kShortJob), job_ended)["state"], "done");
}

}  // namespace
}  // namespace geodesic::test
