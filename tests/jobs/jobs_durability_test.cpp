// Jobs survive a killed daemon: SIGKILL in the middle of a running job, start again on the same
// data directory, and every accepted job is still there, a finished job's files are the same
// bytes, and the running job resumes from its checkpoint (its sample count goes on, not from 0)
// and completes.
#include <csignal>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "job_daemon.h"
#include "render/image_io.h"

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

bool ended(const json& status) { return status["state"] != "queued" && status["state"] != "running"; }

TEST(JobsDurability, SigkillThenRestartResumesFromTheCheckpoint) {
  TempDir data;
  const fs::path dir = data.path() / "data";
  const std::vector<std::string> args = {"--max-jobs", "1", "--checkpoint-seconds", "1"};
  // Long enough to be killed in the middle on any machine: seconds of furnace paths.
  constexpr int kSpp = 1500;
  const json long_job = {{"scene", "furnace"}, {"width", 64}, {"height", 48}, {"spp", kSpp},
                         {"formats", {"exr", "png"}}};
  const json short_job = {{"scene", "furnace"}, {"width", 32}, {"height", 24}, {"spp", 8},
                          {"formats", {"png"}}};

  int64_t finished = 0, interrupted = 0, waiting = 0;
  std::string finished_png;
  json at_kill;
  {
    DaemonProcess daemon(dir, args);
    const JobsApi api(daemon.port());
    finished = api.submit(short_job);
    ASSERT_EQ(api.wait_for(finished, ended, std::chrono::seconds(240))["state"], "done");
    finished_png = file_bytes(dir / "jobs" / std::to_string(finished) / "result.png");
    ASSERT_FALSE(finished_png.empty());

    interrupted = api.submit(long_job);
    waiting = api.submit(short_job);  // queued behind it (--max-jobs 1)
    at_kill = api.wait_for(interrupted, [](const json& s) {
      return s["checkpoint_samples"].get<int>() > 0 || ended(s);
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
  const json done = api.wait_for(interrupted, ended, std::chrono::seconds(240));
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_EQ(done["samples"], kSpp);
  // Elapsed time goes on from the checkpoint's too (taken at most a second and a pass before).
  EXPECT_GT(done["elapsed"].get<double>(), at_kill["elapsed"].get<double>() - 1.5);
  uint32_t previous = 0;
  for (const json& point : done["series"]) {  // the series goes on across the restart
    EXPECT_GE(point["spp"].get<uint32_t>(), previous);
    previous = point["spp"].get<uint32_t>();
  }
  EXPECT_EQ(previous, uint32_t(kSpp));

  const Image image = read_image(dir / "jobs" / std::to_string(interrupted) / "result.exr");
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
  double sum = 0;
  for (float v : image.rgb) sum += v;
  EXPECT_NEAR(sum / double(image.rgb.size()), 2.0, 0.1);  // still the furnace's radiance
  EXPECT_FALSE(fs::exists(dir / "jobs" / std::to_string(interrupted) / "checkpoint.bin"));

  EXPECT_EQ(api.wait_for(waiting, ended)["state"], "done");
}

}  // namespace
}  // namespace geodesic::test
