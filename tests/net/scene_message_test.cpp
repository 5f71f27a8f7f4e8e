// What the server tells a client about its scene and limits, so the client guesses neither:
// `hello` carries the server's own max_depth (not the default 16), and each `scene` message
// says how the scene was given (bundled, document, generators) and its title.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "daemon_fixture.h"

namespace geodesic::test {
namespace {

using nlohmann::json;

constexpr const char* kSphere = R"({"geometry": "euclidean", "camera": {"position": [0, 0, 3]},
  "materials": {"m": {"diffuse": 0.5}},
  "objects": [{"type": "sphere", "material": "m", "center": [0, 0, 0], "radius": 1}]})";

TEST(SceneMessages, HelloCarriesTheServersMaxDepthAndSettingsAreBoundByIt) {
  DaemonOptions options;
  options.limits.max_depth = 7;
  Daemon daemon(options);
  WsClient client(daemon.port());
  const json hello = client.read_until("hello");
  EXPECT_EQ(hello["limits"]["max_depth"], 7);

  const json first = client.read_scene();
  EXPECT_EQ(first["name"], "cornell-box");
  EXPECT_EQ(first["source"], "bundled");
  EXPECT_TRUE(first["title"].get<std::string>().starts_with("Cornell box")) << first["title"];

  client.send({{"type", "settings"}, {"width", 64}, {"height", 48}, {"max_depth", 8}});
  const json error = client.read_until("error");
  EXPECT_EQ(error["field"], "max_depth");
  EXPECT_EQ(error["message"], "must be in [0, 7]");
  // The limit itself is accepted: frames of 64x48 come (the refused message changed nothing).
  client.send({{"type", "settings"}, {"width", 64}, {"height", 48}, {"max_depth", 7}});
  const auto frame = client.read_frame_where([](const json& f) { return f["width"] == 64; });
  EXPECT_EQ(frame.info["height"], 48);

  // A scene asking for more depth than the server gives is refused, naming its field.
  json deep_document = json::parse(kSphere);
  deep_document["render"] = {{"max_depth", 8}};
  client.send({{"type", "open"}, {"document", deep_document}});
  const json deep = client.read_until("error");
  EXPECT_EQ(deep["field"], "document.render.max_depth");
  EXPECT_EQ(deep["message"], "must be <= 7 on this server");
}

TEST(SceneMessages, EachSourceSaysWhatItIs) {
  Daemon daemon;
  WsClient client(daemon.port());
  client.read_scene();
  client.send({{"type", "settings"}, {"width", 64}, {"height", 48}});

  client.send({{"type", "open"}, {"scene", "torus-cornell"}});
  const json bundled = client.read_scene();
  EXPECT_EQ(bundled["name"], "torus-cornell");
  EXPECT_EQ(bundled["source"], "bundled");
  EXPECT_TRUE(bundled["title"].get<std::string>().starts_with("Cornell box in the 3-torus"))
      << bundled["title"];

  std::ifstream in(std::string(GEODESIC_SOURCE_DIR) + "/catalogue/lens-7-2.gen");
  std::ostringstream text;
  text << in.rdbuf();
  client.send({{"type", "open"}, {"generators", text.str()}});
  const json space = client.read_scene();
  EXPECT_EQ(space["name"], "Lens space L(7,2)");
  EXPECT_EQ(space["source"], "generators");
  EXPECT_EQ(space["title"], "Lens space L(7,2)");
  EXPECT_EQ(space["geometry"], "spherical");

  // A document may take a bundled scene's name: `source` still tells them apart.
  const json sphere = json::parse(kSphere);
  json named = sphere;
  named["name"] = "cornell-box";
  client.send({{"type", "open"}, {"document", named}});
  const json impostor = client.read_scene();
  EXPECT_EQ(impostor["name"], "cornell-box");
  EXPECT_EQ(impostor["source"], "document");

  client.send({{"type", "open"}, {"document", sphere}});
  const json unnamed = client.read_scene();
  EXPECT_EQ(unnamed["name"], "document");
  EXPECT_EQ(unnamed["source"], "document");
  EXPECT_EQ(unnamed["title"], "document");
}

}  // namespace
}  // namespace geodesic::test
