// What an operator needs and what a careless client sends: finished jobs removed with their
// files (`DELETE ?remove=true`, 409 while one runs), `--keep-jobs` retention, `GET /api/jobs`
// pages, and the small refusals: invalid UTF-8 (400 JSON), cameras that are not isometries,
// a lower-case bearer scheme, a blank token, `--host localhost`, `--max-depth`.
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "job_daemon.h"

namespace geodesic::test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

json small_job(int spp = 2) {
  return {{"scene", "furnace"}, {"width", 16}, {"height", 16}, {"spp", spp}, {"formats", {"png"}}};
}

TEST(JobsOperator, FinishedJobsAreRemovedWithTheirFilesAndRunningOnesRefused) {
  TempDir data;
  const fs::path dir = data.path() / "data";
  DaemonProcess daemon(dir, {"--max-jobs", "1"});
  const JobsApi api(daemon.port());
  const int64_t done = api.submit(small_job());
  api.wait_for(done, job_ended);
  ASSERT_TRUE(fs::exists(dir / "jobs" / std::to_string(done) / "result.png"));
  const int64_t running = api.submit(small_job(1 << 20));
  api.wait_for(running, [](const json& s) { return s["state"] == "running"; });

  const std::string remove = "/api/jobs/" + std::to_string(running) + "?remove=true";
  const ApiReply refused = api.request(http::verb::delete_, remove);
  EXPECT_EQ(refused.status, 409u) << refused.body;
  EXPECT_TRUE(refused.json["error"].get<std::string>().starts_with("state: job")) << refused.body;

  const ApiReply removed =
      api.request(http::verb::delete_, "/api/jobs/" + std::to_string(done) + "?remove=true");
  EXPECT_EQ(removed.status, 200u) << removed.body;
  EXPECT_EQ(api.get("/api/jobs/" + std::to_string(done)).status, 404u);
  EXPECT_FALSE(fs::exists(dir / "jobs" / std::to_string(done)));
  EXPECT_EQ(api.request(http::verb::delete_, "/api/jobs/" + std::to_string(done) + "?remove=true").status,
            404u);

  // Cancel first, then remove.
  EXPECT_EQ(api.request(http::verb::delete_, "/api/jobs/" + std::to_string(running)).status, 200u);
  EXPECT_EQ(api.request(http::verb::delete_, remove).status, 200u);
  EXPECT_EQ(api.get("/api/jobs").json["jobs"].size(), 0u);
  const int64_t next = api.submit(small_job());
  EXPECT_GT(next, running);  // ids are not reused after a removal
}

TEST(JobsOperator, KeepJobsRetainsTheNewestFinishedJobs) {
  TempDir data;
  const fs::path dir = data.path() / "data";
  DaemonProcess daemon(dir, {"--keep-jobs", "2"});
  const JobsApi api(daemon.port());
  std::vector<int64_t> ids;
  for (int i = 0; i < 4; ++i) {
    ids.push_back(api.submit(small_job()));
    api.wait_for(ids.back(), job_ended);
  }
  json list;
  for (int i = 0; i < 50; ++i) {  // the scheduler retains within a poll or two
    list = api.get("/api/jobs").json;
    if (list["jobs"].size() == 2) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_EQ(list["jobs"].size(), 2u) << list;
  EXPECT_EQ(list["jobs"][0]["id"], ids[2]);
  EXPECT_EQ(list["jobs"][1]["id"], ids[3]);
  EXPECT_FALSE(fs::exists(dir / "jobs" / std::to_string(ids[0])));
  EXPECT_TRUE(fs::exists(dir / "jobs" / std::to_string(ids[3]) / "result.png"));
}

TEST(JobsOperator, JobListsComeInPages) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data", {"--max-jobs", "1"});
  const JobsApi api(daemon.port());
  std::vector<int64_t> ids;
  for (int i = 0; i < 5; ++i) ids.push_back(api.submit(small_job()));
  const ApiReply first = api.get("/api/jobs?limit=2");
  ASSERT_EQ(first.status, 200u) << first.body;
  ASSERT_EQ(first.json["jobs"].size(), 2u);
  EXPECT_EQ(first.json["jobs"][1]["id"], ids[1]);
  const std::string next = first.json["next"].get<std::string>();
  EXPECT_EQ(next, "/api/jobs?limit=2&after=" + std::to_string(ids[1]));
  const ApiReply second = api.get(next);
  ASSERT_EQ(second.json["jobs"].size(), 2u);
  EXPECT_EQ(second.json["jobs"][0]["id"], ids[2]);
  const ApiReply last = api.get("/api/jobs?limit=2&after=" + std::to_string(ids[3]));
  ASSERT_EQ(last.json["jobs"].size(), 1u);
  EXPECT_FALSE(last.json.contains("next"));
  EXPECT_EQ(api.get("/api/jobs").json["jobs"].size(), 5u);
  const ApiReply bad = api.get("/api/jobs?limit=x");
  EXPECT_EQ(bad.status, 400u);
  EXPECT_EQ(bad.json["error"], "limit: must be an integer in [0, 1000]");
  EXPECT_EQ(api.get("/api/jobs?limit=0").status, 400u);
  EXPECT_EQ(api.get("/api/jobs?after=-1").status, 400u);
}

TEST(JobsOperator, CarelessInputGetsNamedRefusals) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data");
  const JobsApi api(daemon.port());
  // Invalid UTF-8 inside a string: 400 JSON, not 500 text.
  const ApiReply utf8 = api.request(http::verb::post, "/api/jobs",
                                    "{\"scene\": \"furn\xff\xfe\", \"spp\": 1}");
  EXPECT_EQ(utf8.status, 400u) << utf8.body;
  EXPECT_EQ(utf8.content_type, "application/json");
  const std::string reason = utf8.json["error"];
  EXPECT_TRUE(reason.starts_with("body: invalid JSON")) << reason;
  EXPECT_NE(reason.find("ill-formed UTF-8"), std::string::npos) << reason;
  // Cameras that are no isometry of the scene's space.
  for (const double value : {0.0, 1e300}) {
    json job = small_job();
    job["camera"] = std::vector<double>(16, value);
    const ApiReply reply = api.post("/api/jobs", job);
    EXPECT_EQ(reply.status, 400u) << reply.body;
    EXPECT_TRUE(reply.json["error"].get<std::string>().starts_with("camera: not an isometry"))
        << reply.body;
  }
  json identity = small_job();
  identity["camera"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_EQ(api.post("/api/jobs", identity).status, 202u);
}

// `--max-depth` bounds a job's max_depth as it bounds a session's (hello.limits.max_depth):
// 40 is past the default 16.
TEST(JobsOperator, MaxDepthIsTheServersOwn) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data", {"--max-depth", "40"});
  const JobsApi api(daemon.port());
  json deep = small_job();
  deep["max_depth"] = 40;
  EXPECT_EQ(api.post("/api/jobs", deep).status, 202u);
  deep["max_depth"] = 41;
  const ApiReply refused = api.post("/api/jobs", deep);
  EXPECT_EQ(refused.status, 400u);
  EXPECT_EQ(refused.json["error"], "max_depth: must be an integer in [0, 40]");
  std::string output;
  EXPECT_NE(run_cli({"serve", "--max-depth", "65", "--data", (data.path() / "b").string()}, output), 0);
  EXPECT_NE(output.find("--max-depth: must be an integer in [0, 64]"), std::string::npos) << output;
}

TEST(JobsOperator, TokensAndHostsAreCheckedAsWritten) {
  TempDir data;
  std::string output;
  EXPECT_NE(run_cli({"serve", "--host", "0.0.0.0", "--port", "0", "--token", " ", "--data",
                     (data.path() / "a").string()},
                    output),
            0);
  EXPECT_NE(output.find("--token: must be printable characters without spaces"), std::string::npos)
      << output;
  {
    DaemonProcess daemon(data.path() / "b", {"--host", "localhost", "--token", "lower-case-1"});
    HttpHeaders lower = {{http::field::authorization, "bearer lower-case-1"}};
    EXPECT_EQ(http_request(daemon.port(), http::verb::get, "/api/jobs", "", lower).result_int(), 200u);
    HttpHeaders upper = {{http::field::authorization, "BEARER lower-case-1"}};
    EXPECT_EQ(http_request(daemon.port(), http::verb::get, "/api/jobs", "", upper).result_int(), 200u);
    HttpHeaders wrong = {{http::field::authorization, "bearer lower-case-2"}};
    EXPECT_EQ(http_request(daemon.port(), http::verb::get, "/api/jobs", "", wrong).result_int(), 401u);
  }
}

}  // namespace
}  // namespace geodesic::test
