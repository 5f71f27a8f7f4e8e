// The jobs API of a real `geodesic serve` on 127.0.0.1: a job's life from submission to its
// files, cancellation, the queue limit, and the errors for bad requests. Every answer is
// checked against proto/openapi.json.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "job_daemon.h"
#include "render/prepare/image_io.h"

namespace geodesic::test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// The white furnace (docs: radiance converges to emission / (1 - albedo) = 2) at a small size.
json furnace_job(int spp) {
  return {{"scene", "furnace"}, {"width", 32}, {"height", 24}, {"spp", spp}};
}

Image decode(const std::string& bytes, const TempDir& dir, const std::string& extension) {
  const fs::path file = dir.path() / ("download." + extension);
  std::ofstream(file, std::ios::binary) << bytes;
  return read_image(file);
}

std::string job_path(int64_t id, const std::string& rest = "") {
  return "/api/jobs/" + std::to_string(id) + rest;
}

TEST(JobsApi, JobRunsToItsFilesAndReport) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data");
  const JobsApi api(daemon.port());

  json request = furnace_job(64);
  request["exposure"] = -2;  // the PNG and JPEG show a quarter of the radiance 2: unclipped
  const int64_t id = api.submit(request);
  const ApiReply list = api.get("/api/jobs");
  ASSERT_EQ(list.status, 200u);
  for (const auto& error : openapi_errors(list.json, "JobList")) ADD_FAILURE() << error;
  ASSERT_EQ(list.json["jobs"].size(), 1u);
  EXPECT_EQ(list.json["jobs"][0]["id"], id);

  const json done = api.wait_for(id, [](const json& s) { return s["state"] != "queued" && s["state"] != "running"; },
                                 std::chrono::seconds(240));
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_EQ(done["samples"], 64);
  EXPECT_EQ(done["progress"], 1.0);
  EXPECT_GT(done["estimated_error"].get<double>(), 0.0);
  EXPECT_EQ(done["non_finite_samples"], 0);
  EXPECT_EQ(done["truncated_geodesics"], 0);  // a furnace has no faces to cross
  ASSERT_FALSE(done["series"].empty());
  EXPECT_EQ(done["series"].back()["spp"], 64);
  for (const char* format : {"exr", "png", "jpg"})
    EXPECT_EQ(done["results"][format], job_path(id, std::string("/result.") + format));

  TempDir downloads;
  const ApiReply exr = api.get(job_path(id, "/result.exr"));
  ASSERT_EQ(exr.status, 200u);
  EXPECT_EQ(exr.content_type, "image/x-exr");
  const Image image = decode(exr.body, downloads, "exr");
  EXPECT_EQ(image.width, 32);
  EXPECT_EQ(image.height, 24);
  double sum = 0;
  for (float v : image.rgb) sum += v;
  EXPECT_NEAR(sum / double(image.rgb.size()), 2.0, 0.2);  // the furnace's radiance
  for (const char* format : {"png", "jpg"}) {
    const ApiReply reply = api.get(job_path(id, std::string("/result.") + format));
    ASSERT_EQ(reply.status, 200u) << format;
    const Image decoded = decode(reply.body, downloads, format);
    EXPECT_EQ(decoded.width, 32) << format;
    EXPECT_EQ(decoded.height, 24) << format;
    // The EXR's radiance times 2^-2 through the sRGB curve: code for code in the PNG, within
    // the JPEG's error in the JPEG.
    double off = 0;
    for (size_t i = 0; i < image.rgb.size(); ++i)
      off = std::max(off, std::abs(double(to_srgb8(decoded.rgb[i])) - to_srgb8(image.rgb[i] / 4)));
    EXPECT_LE(off, format == std::string("png") ? 1 : 12) << format;
  }

  const ApiReply report = api.get(job_path(id, "/report.json"));
  ASSERT_EQ(report.status, 200u);
  for (const auto& error : openapi_errors(report.json, "JobReport")) ADD_FAILURE() << error;
  EXPECT_EQ(report.json["stop"]["spp"], 64);
  EXPECT_EQ(report.json["series"], done["series"]);
  const ApiReply csv = api.get(job_path(id, "/report.csv"));
  ASSERT_EQ(csv.status, 200u);
  EXPECT_TRUE(csv.body.starts_with("seconds,spp,estimated_error\n"));
  EXPECT_EQ(std::count(csv.body.begin(), csv.body.end(), '\n'), long(done["series"].size()) + 1);

  // The served OpenAPI document is proto/openapi.json.
  std::ifstream source(GEODESIC_SOURCE_DIR "/proto/openapi.json");
  EXPECT_EQ(api.get("/api/openapi.json").json, json::parse(source));
}

TEST(JobsApi, StopsAfterSecondsOrAtTheTargetError) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data", {"--max-jobs", "2"});
  const JobsApi api(daemon.port());
  const auto job = [](const char* stop, double value) {
    return json{{"scene", "furnace"}, {"width", 32}, {"height", 24}, {stop, value}, {"formats", {"png"}}};
  };
  const int64_t timed = api.submit(job("seconds", 1.0));
  const int64_t precise = api.submit(job("target_error", 0.05));
  const auto done = [](const json& s) { return s["state"] == "done"; };

  // Each stops at the end of the first pass that meets its condition: every earlier point of
  // its series falls short of it.
  const json after_seconds = api.wait_for(timed, done, std::chrono::seconds(240));
  EXPECT_GE(after_seconds["elapsed"].get<double>(), 1.0);
  EXPECT_GT(after_seconds["samples"].get<int>(), 0);
  const json& timed_series = after_seconds["series"];
  for (size_t i = 0; i + 1 < timed_series.size(); ++i) EXPECT_LT(timed_series[i]["seconds"].get<double>(), 1.0);

  const json after_error = api.wait_for(precise, done, std::chrono::seconds(240));
  EXPECT_LE(after_error["estimated_error"].get<double>(), 0.05);
  EXPECT_GE(after_error["samples"].get<int>(), 8);
  EXPECT_EQ(after_error["progress"], 1.0);
  const json& precise_series = after_error["series"];
  for (size_t i = 0; i + 1 < precise_series.size(); ++i)
    if (precise_series[i]["spp"].get<int>() >= 8) EXPECT_GT(precise_series[i]["estimated_error"].get<double>(), 0.05);
}

TEST(JobsApi, CancelQueueLimitAndStates) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data", {"--max-jobs", "1", "--max-queue", "1"});
  const JobsApi api(daemon.port());

  const int64_t running = api.submit(furnace_job(1 << 20));
  api.wait_for(running, [](const json& s) { return s["samples"].get<int>() > 0; },
               std::chrono::seconds(240));
  const int64_t queued = api.submit(furnace_job(16));
  EXPECT_EQ(api.get(job_path(queued)).json["state"], "queued");

  const ApiReply full = api.post("/api/jobs", furnace_job(16));
  EXPECT_EQ(full.status, 429u);
  EXPECT_TRUE(full.json["error"].get<std::string>().starts_with("queue:")) << full.body;
  EXPECT_EQ(api.get(job_path(queued, "/result.png")).status, 409u);

  const ApiReply cancel_queued = api.request(http::verb::delete_, job_path(queued));
  EXPECT_EQ(cancel_queued.status, 200u);
  EXPECT_EQ(cancel_queued.json["state"], "cancelled");
  const ApiReply cancel_running = api.request(http::verb::delete_, job_path(running));
  EXPECT_EQ(cancel_running.status, 200u);
  EXPECT_EQ(cancel_running.json["state"], "cancelled");
  EXPECT_GT(cancel_running.json["samples"].get<int>(), 0);
  // The runner deletes the checkpoint when it next has the device (within a slice or two).
  const fs::path checkpoint = data.path() / "data" / "jobs" / std::to_string(running) / "checkpoint.bin";
  for (int i = 0; i < 50 && fs::exists(checkpoint); ++i) std::this_thread::sleep_for(100ms);
  EXPECT_FALSE(fs::exists(checkpoint));

  EXPECT_EQ(api.request(http::verb::delete_, job_path(running)).status, 409u);
  EXPECT_EQ(api.request(http::verb::delete_, job_path(9999)).status, 404u);
  // The reply is held: iterating a member of the temporary read freed memory (ASan).
  const ApiReply jobs = api.get("/api/jobs");
  for (const json& job : jobs.json["jobs"]) EXPECT_EQ(job["state"], "cancelled");

  // The queue goes on after cancellations.
  const int64_t next = api.submit(furnace_job(8));
  EXPECT_EQ(api.wait_for(next, [](const json& s) { return s["state"] == "done"; })["samples"], 8);
}

// A space given only by generator text (what the browser sends for a dropped file) renders in
// the default scene of its space, and the job keeps that scene document.
TEST(JobsApi, GeneratorTextRendersItsSpace) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data");
  const JobsApi api(daemon.port());
  std::ifstream in(GEODESIC_SOURCE_DIR "/catalogue/lens-7-2.gen");
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  const int64_t id = api.submit(
      {{"generators", text}, {"width", 32}, {"height", 24}, {"spp", 4}, {"formats", {"png"}}});
  const json done = api.wait_for(id, [](const json& s) { return s["state"] != "queued" && s["state"] != "running"; },
                                 std::chrono::seconds(240));
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_EQ(done["scene"], "Lens space L(7,2)");  // the text's first comment line
  EXPECT_EQ(done["request"]["scene"]["manifold"]["type"], "generators");
  EXPECT_FALSE(done["request"].contains("generators"));
  TempDir downloads;
  const ApiReply png = api.get(job_path(id, "/result.png"));
  ASSERT_EQ(png.status, 200u);
  const Image image = decode(png.body, downloads, "png");
  ASSERT_EQ(image.width, 32);
  double brightest = 0;
  for (float v : image.rgb) brightest = std::max(brightest, double(v));
  EXPECT_GT(brightest, 0.2);  // the spheres inside the lens space, not an empty frame
}

// A geodesic that runs out of face crossings is counted in the job's status and in /metrics:
// in the 3-torus with one crossing allowed many are cut off, with 64 far fewer.
TEST(JobsApi, StatusAndMetricsCountGeodesicsCutOffAtTheCrossingCap) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data");
  const JobsApi api(daemon.port());
  std::ifstream in(GEODESIC_SOURCE_DIR "/scenes/torus-lamps.json");
  json scene = json::parse(in);
  uint64_t truncated[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    scene["manifold"]["max_crossings"] = i == 0 ? 1 : 64;
    const int64_t id = api.submit(
        {{"scene", scene}, {"width", 32}, {"height", 24}, {"spp", 4}, {"formats", {"png"}}});
    const json done = api.wait_for(
        id, [](const json& s) { return s["state"] != "queued" && s["state"] != "running"; },
        std::chrono::seconds(240));
    ASSERT_EQ(done["state"], "done") << done.dump();
    EXPECT_EQ(done["non_finite_samples"], 0);
    truncated[i] = done["truncated_geodesics"].get<uint64_t>();
  }
  EXPECT_GT(truncated[0], 32u * 24u);  // more than one per pixel over the 4 samples
  EXPECT_LT(truncated[1] * 10, truncated[0]);
  const ApiReply metrics = api.get("/metrics");
  ASSERT_EQ(metrics.status, 200u);
  const std::string line = "\ngeodesic_truncated_geodesics_total " +
                           std::to_string(truncated[0] + truncated[1]) + "\n";
  EXPECT_NE(metrics.body.find(line), std::string::npos) << metrics.body;
  EXPECT_NE(metrics.body.find("\ngeodesic_non_finite_samples_total 0\n"), std::string::npos);
}

TEST(JobsApi, BadRequestsNameTheField) {
  TempDir data;
  DaemonProcess daemon(data.path() / "data");
  const JobsApi api(daemon.port());
  auto error_of = [&](const std::string& body) {
    const ApiReply reply = api.request(http::verb::post, "/api/jobs", body);
    EXPECT_EQ(reply.status, 400u) << body;
    return reply.json.value("error", std::string());
  };
  auto starts = [](const std::string& text, const std::string& prefix) {
    return text.starts_with(prefix) ? ::testing::AssertionSuccess()
                                    : ::testing::AssertionFailure() << text;
  };
  const json job = furnace_job(16);
  auto with = [&](const std::string& field, const json& value) {
    json changed = job;
    changed[field] = value;
    return changed.dump();
  };
  EXPECT_TRUE(starts(error_of("{\"scene\": "), "body: invalid JSON"));
  // A number beyond double's range is out_of_range in nlohmann, not parse_error: was a 500.
  EXPECT_TRUE(starts(error_of(R"({"scene": "furnace", "spp": 1e400})"), "body: invalid JSON"));
  EXPECT_TRUE(starts(error_of("[1, 2]"), "body: must be a JSON object"));
  EXPECT_TRUE(starts(error_of(with("colour", "red")), "colour: unknown field"));
  EXPECT_TRUE(starts(error_of(with("exposure", "bright")),
                     "exposure: must be a number of stops in [-20, 20] or \"auto\""));
  EXPECT_TRUE(starts(error_of(with("exposure", 21)), "exposure: must be a number of stops"));
  json no_scene = job;
  no_scene.erase("scene");
  EXPECT_TRUE(starts(error_of(no_scene.dump()), "scene: give exactly one of scene and generators"));
  EXPECT_TRUE(starts(error_of(with("generators", "1 0 0 0")), "generators: give exactly one of"));
  no_scene["generators"] = 42;
  EXPECT_TRUE(starts(error_of(no_scene.dump()), "generators: must be the text of a generator file"));
  no_scene["generators"] = "1 0 0 0\n0 1 0\n0 0 1 0\n0 0 0 1\n";
  EXPECT_TRUE(starts(error_of(no_scene.dump()), "generators: matrix 1 (line 2): row 2 has 3 entries"));
  EXPECT_TRUE(starts(error_of(with("scene", "atlantis")), "scene: unknown bundled scene"));
  const json document = {{"geometry", "euclidean"},
                         {"camera", {{"position", {0, 0, 0}}, {"look_at", {0, 0, -1}}, {"fov_y", 60}}},
                         {"materials", {{"m", {{"diffuse", 0.5}}}}},
                         {"objects", {{{"type", "sphere"}, {"material", "m"}, {"center", {0, 0, -3}}, {"radius", -1}}}}};
  EXPECT_TRUE(starts(error_of(with("scene", document)), "scene.objects[0].radius:"));
  EXPECT_TRUE(starts(error_of(with("width", 100000)), "width: must be an integer in [16, 1920]"));
  EXPECT_TRUE(starts(error_of(with("height", "tall")), "height:"));
  EXPECT_TRUE(starts(error_of(with("spp", 0)), "spp:"));
  EXPECT_TRUE(starts(error_of(with("seconds", 5)), "spp: give exactly one stop condition"));
  json no_stop = job;
  no_stop.erase("spp");
  EXPECT_TRUE(starts(error_of(no_stop.dump()), "spp: give exactly one stop condition"));
  EXPECT_TRUE(starts(error_of(with("formats", {"png", "gif"})), "formats[1]:"));
  EXPECT_TRUE(starts(error_of(with("camera", {1, 2, 3})), "camera:"));
  EXPECT_TRUE(starts(error_of(with("max_depth", 99)), "max_depth:"));

  // Too big: a body over the limit (1 MiB) is 413, answered from its header, and the
  // connection closes.
  const RawReply huge = raw_exchange(
      daemon.port(), "POST /api/jobs HTTP/1.1\r\nHost: x\r\nContent-Length: 2097152\r\n\r\n", 10s);
  EXPECT_TRUE(huge.data.starts_with("HTTP/1.1 413")) << huge.data;
  EXPECT_NE(huge.data.find("{\"error\":\"body: larger than 1048576 bytes\"}"), std::string::npos);
  EXPECT_TRUE(huge.closed);

  EXPECT_EQ(api.get("/api/jobs/12345").status, 404u);
  EXPECT_EQ(api.get("/api/jobs/not-a-number").status, 404u);
  EXPECT_EQ(api.get("/api/jobs/1/result.gif").status, 404u);
  EXPECT_EQ(api.request(http::verb::put, "/api/jobs").status, 405u);
  EXPECT_TRUE(api.get("/api/jobs").json["jobs"].empty());  // nothing invalid was stored
}

}  // namespace
}  // namespace geodesic::test
