// The WebSocket protocol against a real daemon: handshake, frames and their JPEGs, moves,
// accumulation, errors, limits, slow readers, shutdown. Frames are 64x48 to keep each test to a
// few seconds on lavapipe.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include "daemon_fixture.h"

namespace geodesic::test {
namespace {

using nlohmann::json;

const json kSmallFrames = {{"type", "settings"}, {"width", 64}, {"height", 48}};

bool is_small(const json& frame) { return frame["width"] == 64 && frame["height"] == 48; }

int open_sessions(uint16_t port) {
  return json::parse(http_get(port, "/healthz").body())["sessions"].get<int>();
}

TEST(WebSocket, HelloThenSceneThenFramesWithTheirJpeg) {
  Daemon daemon;
  WsClient client(daemon.port());
  const json hello = client.read_json();
  ASSERT_EQ(hello["type"], "hello");
  EXPECT_EQ(hello["limits"]["max_message_bytes"], 1 << 20);
  EXPECT_EQ(hello["limits"]["idle_timeout_seconds"], 600);
  EXPECT_EQ(hello["limits"]["max_depth"], 16);
  EXPECT_NE(std::find(hello["scenes"].begin(), hello["scenes"].end(), "cornell-box"),
            hello["scenes"].end());
  const json scene = client.read_json();
  ASSERT_EQ(scene["type"], "scene");
  EXPECT_EQ(scene["name"], "cornell-box");
  EXPECT_EQ(scene["geometry"], "euclidean");

  // Without asking, the default scene streams at its own size.
  const auto first = client.read_frame();
  EXPECT_EQ(first.info["width"], scene["width"]);

  client.send(kSmallFrames);
  uint64_t last_number = first.info["frame"];
  for (int i = 0; i < 3; ++i) {
    const auto frame = client.read_frame_where(is_small);
    ASSERT_GE(frame.jpeg.size(), 4u);
    EXPECT_EQ(static_cast<unsigned char>(frame.jpeg[0]), 0xFF);  // JPEG SOI marker
    EXPECT_EQ(static_cast<unsigned char>(frame.jpeg[1]), 0xD8);
    EXPECT_EQ(static_cast<unsigned char>(frame.jpeg.back()), 0xD9);  // EOI
    EXPECT_GT(frame.info["frame"].get<uint64_t>(), last_number);
    last_number = frame.info["frame"];
  }
}

TEST(WebSocket, MoveResetsAccumulationAndMovesTheCamera) {
  Daemon daemon;
  WsClient client(daemon.port());
  client.send(kSmallFrames);
  const auto still = client.read_frame_where([](const json& f) { return is_small(f) && f["spp"] >= 16; });
  client.send({{"type", "move"}, {"forward", 0.3}, {"yaw", 5}});
  const auto moved =
      client.read_frame_where([&](const json& f) { return f["camera"] != still.info["camera"]; });
  EXPECT_LT(moved.info["spp"], still.info["spp"]);
  EXPECT_LT(moved.info["elapsed"], still.info["elapsed"]);
}

TEST(WebSocket, StillCameraAccumulatesAndTheErrorFalls) {
  Daemon daemon;
  WsClient client(daemon.port());
  client.send(kSmallFrames);
  const auto early =
      client.read_frame_where([](const json& f) { return is_small(f) && !f["error"].is_null(); });
  const uint32_t early_spp = early.info["spp"];
  const auto later = client.read_frame_where(
      [&](const json& f) { return is_small(f) && f["spp"] >= 16 * early_spp; });
  EXPECT_GT(later.info["elapsed"], early.info["elapsed"]);
  // The error falls as 1/sqrt(spp): 16 times the samples, a quarter of the error.
  EXPECT_LT(later.info["error"].get<double>(), 0.7 * early.info["error"].get<double>());
}

TEST(WebSocket, BadMessagesGetAnErrorAndTheSessionGoesOn) {
  Daemon daemon;
  WsClient client(daemon.port());
  client.send(kSmallFrames);
  const std::pair<std::string, std::string> cases[] = {
      {"{not json", ""},
      {R"({"type":"move","forward":1e400})", ""},  // number overflow: once ended the daemon
      {R"({"type":"jump"})", "type"},
      {R"({"type":"move","forward":"far"})", "forward"},
      {R"({"type":"settings","width":8})", "width"},
      {R"({"type":"open"})", "scene"},
      {R"({"type":"open","document":{"geometry":"euclidean",
          "camera":{"position":[0,0,3],"look_at":[0,0,0],"up":[0,1,0]},
          "materials":{"m":{"diffuse":0.5}},
          "objects":[{"type":"sphere","material":"m","center":[0,0,0],"radius":-1}]}})",
       "document.objects[0].radius"},
      // Outside the scene directory: once answered with the file's first token.
      {R"({"type":"open","document":{"geometry":"euclidean","camera":{"position":[0,0,3]},
          "manifold":{"type":"generators","file":"/etc/passwd"}}})",
       "document.manifold.file"},
  };
  for (const auto& [text, field] : cases) {
    ASSERT_FALSE(client.send_raw(text));
    const json error = client.read_until("error");
    EXPECT_EQ(error["field"], field) << text << " -> " << error["message"];
    EXPECT_FALSE(error["message"].get<std::string>().empty());
  }
  ASSERT_FALSE(client.send_raw("\x01\x02", /*binary=*/true));
  EXPECT_EQ(client.read_until("error")["field"], "");
  EXPECT_TRUE(is_small(client.read_frame_where(is_small).info));  // still streaming
}

TEST(WebSocket, UnknownSceneIsAnErrorNamingScene) {
  Daemon daemon;
  WsClient client(daemon.port());
  client.send({{"type", "open"}, {"scene", "no-such-scene"}});
  const json error = client.read_until("error");
  EXPECT_EQ(error["field"], "scene");
  EXPECT_NE(error["message"].get<std::string>().find("no-such-scene"), std::string::npos);

  client.send({{"type", "open"}, {"scene", "spherical-spheres"}});
  const json scene = client.read_scene();
  json next = scene;
  if (scene["name"] == "cornell-box") next = client.read_scene();  // the default's first
  EXPECT_EQ(next["name"], "spherical-spheres");
  EXPECT_EQ(next["geometry"], "spherical");
}

// A dropped .gen file: its text opens the default scene inside that space; bad text is an
// error naming the generators field, the matrix and the line.
TEST(WebSocket, GeneratorTextOpensTheSpaceItDescribes) {
  Daemon daemon;
  WsClient client(daemon.port());
  std::ifstream in(std::string(GEODESIC_SOURCE_DIR) + "/catalogue/lens-7-2.gen");
  std::ostringstream text;
  text << in.rdbuf();
  client.send({{"type", "open"}, {"generators", text.str()}});
  json scene = client.read_scene();
  if (scene["name"] == "cornell-box") scene = client.read_scene();  // the default's first
  EXPECT_EQ(scene["name"], "Lens space L(7,2)");  // the text's first comment line
  EXPECT_EQ(scene["geometry"], "spherical");
  EXPECT_EQ(scene["manifold"], "generators");

  client.send({{"type", "open"}, {"generators", "1 0 0 0\n0 1 0\n0 0 1 0\n0 0 0 1\n"}});
  const json error = client.read_until("error");
  EXPECT_EQ(error["field"], "generators");
  EXPECT_NE(error["message"].get<std::string>().find("matrix 1 (line 2): row 2 has 3 entries"),
            std::string::npos)
      << error["message"];
}

// Frames count the geodesics cut off at max_crossings (and the non-finite samples) since the
// scene was loaded: growing while it accumulates, kept across a move, in /metrics too, and
// zero again for a scene without faces.
TEST(WebSocket, FramesCountGeodesicsCutOffAtTheCrossingCap) {
  Daemon daemon;
  WsClient client(daemon.port());
  client.read_scene();
  std::ifstream in(std::string(GEODESIC_SOURCE_DIR) + "/scenes/torus-lamps.json");
  json document = json::parse(in);
  document["manifold"]["max_crossings"] = 1;
  client.send({{"type", "open"}, {"document", document}});
  client.read_scene();
  client.send(kSmallFrames);
  const json first = client.read_frame_where(is_small).info;
  EXPECT_GT(first["truncated_geodesics"].get<uint64_t>(), 0u);
  const json later = client.read_frame_where([&](const json& f) {
                       return is_small(f) && f["spp"] > first["spp"];
                     }).info;
  EXPECT_GT(later["truncated_geodesics"], first["truncated_geodesics"]);
  client.send({{"type", "move"}, {"yaw", 10}});
  const json moved = client.read_frame_where([&](const json& f) { return f["moving"] == true; }).info;
  EXPECT_GE(moved["truncated_geodesics"], later["truncated_geodesics"]);
  EXPECT_EQ(moved["non_finite_samples"], 0);
  const std::string metrics = http_get(daemon.port(), "/metrics").body();
  const size_t at = metrics.find("\ngeodesic_truncated_geodesics_total ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_GE(std::stoull(metrics.substr(at + 36)), moved["truncated_geodesics"].get<uint64_t>());

  client.send({{"type", "open"}, {"scene", "cornell-box"}});
  client.read_scene();
  // Its own size (a scene's open resets the frame size): no frame of the torus left in flight.
  const json box = client.read_frame_where([](const json& f) { return f["height"] == 512; }).info;
  EXPECT_EQ(box["truncated_geodesics"], 0);
  EXPECT_EQ(box["non_finite_samples"], 0);
}

TEST(WebSocket, OversizedMessageClosesWith1009) {
  Daemon daemon;
  WsClient client(daemon.port());
  client.read_until("hello");
  const std::string big =
      R"({"type":"move","padding":")" + std::string(1 << 20, 'x') + R"("})";
  client.send_raw(big);  // the server may close before all of it is written
  EXPECT_EQ(client.read_until_close(), 1009);
}

TEST(WebSocket, IdleClientIsClosedWith4000) {
  DaemonOptions options;
  options.idle_timeout = 1s;
  Daemon daemon(options);
  WsClient client(daemon.port());
  EXPECT_EQ(client.read_until("hello")["limits"]["idle_timeout_seconds"], 1);
  client.send(kSmallFrames);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(client.read_until_close(15s), 4000);  // reading frames is not activity
  EXPECT_GE(std::chrono::steady_clock::now() - start, 900ms);
}

TEST(WebSocket, SessionBeyondTheLimitIsClosedWith1013AndClosingFreesTheSlot) {
  DaemonOptions options;
  options.limits.max_sessions = 1;
  Daemon daemon(options);
  {
    WsClient first(daemon.port());
    first.read_until("hello");
    WsClient second(daemon.port());
    EXPECT_EQ(second.read_until_close(10s), 1013);
    EXPECT_EQ(open_sessions(daemon.port()), 1);
    first.close();
  }
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (open_sessions(daemon.port()) != 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(20ms);
  EXPECT_EQ(open_sessions(daemon.port()), 0);
  WsClient third(daemon.port());
  EXPECT_EQ(third.read_json()["type"], "hello");
}

TEST(WebSocket, SlowReaderMakesTheServerDropFramesNotBufferThem) {
  // Small socket buffers on both ends, so that 2 s of frames fill them.
  DaemonOptions options;
  options.socket_send_buffer = 8192;
  Daemon daemon(options);
  WsClient client(daemon.port(), /*receive_buffer=*/8192);
  client.send({{"type", "settings"}, {"width", 128}, {"height", 96}});
  client.read_frame_where([](const json& f) { return f["width"] == 128; });

  const auto& counters = daemon.server().counters();
  const uint64_t dropped_before = counters.frames_dropped;
  std::this_thread::sleep_for(2s);  // not reading
  EXPECT_GT(counters.frames_dropped, dropped_before);
  // Every frame rendered for this (only) session was sent or dropped, but for the one being
  // written, the one waiting, one on its way to the strand and one discarded by the settings
  // change. The counters are read right after the render count, which can take a while (the
  // render thread holds its lock for whole slices).
  const int64_t encoded = daemon.render().stats().frames;
  const int64_t accounted = counters.frames_sent + counters.frames_dropped;
  EXPECT_LE(encoded - accounted, 4);
  const std::string metrics = http_get(daemon.port(), "/metrics").body();
  const auto at = metrics.find("\ngeodesic_frames_dropped_total ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_GT(std::stoull(metrics.substr(at + 31)), 0u);

  // Reading again: the stream goes on with fresh frames, numbers jumping over the dropped ones.
  uint64_t previous = client.read_frame().info["frame"];
  bool jumped = false;
  for (int i = 0; i < 10 && !jumped; ++i) {
    const uint64_t number = client.read_frame().info["frame"];
    jumped = number > previous + 1;
    previous = number;
  }
  EXPECT_TRUE(jumped);
}

TEST(WebSocket, ShutdownClosesSessionsWith1001) {
  Daemon daemon;
  WsClient client(daemon.port());
  client.read_until("hello");
  std::jthread stopper([&] { daemon.server().stop(); });  // joined even if the read throws
  EXPECT_EQ(client.read_until_close(10s), 1001);
}

}  // namespace
}  // namespace geodesic::test
