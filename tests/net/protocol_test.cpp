// Client message parsing, error paths and server messages, without a daemon.
#include <gtest/gtest.h>

#include "net/protocol.h"
#include "scene/scene.h"
#include "schema_check.h"

namespace geodesic::net {
namespace {

using nlohmann::json;

std::string field_of_error(const std::string& text) {
  try {
    parse_client_message(text, ServiceLimits{});
  } catch (const ProtocolError& e) {
    return e.field();
  }
  return "(accepted)";
}

void expect_server_message_valid(const std::string& text) {
  for (const auto& error :
       test::ws_messages_schema().errors(json::parse(text), "/$defs/server_message"))
    ADD_FAILURE() << error << "\n  in " << text;
}

TEST(Protocol, ParsesEachClientMessage) {
  const ServiceLimits limits;
  const auto open = std::get<OpenRequest>(
      parse_client_message(R"({"type":"open","scene":"cornell-box"})", limits));
  EXPECT_EQ(open.scene, "cornell-box");
  EXPECT_FALSE(open.document);

  const auto inline_open = std::get<OpenRequest>(
      parse_client_message(R"({"type":"open","document":{"geometry":"euclidean"}})", limits));
  ASSERT_TRUE(inline_open.document);
  EXPECT_EQ((*inline_open.document)["geometry"], "euclidean");

  const auto generators = std::get<OpenRequest>(
      parse_client_message(R"({"type":"open","generators":"# a .gen file"})", limits));
  EXPECT_EQ(generators.generators, "# a .gen file");
  EXPECT_FALSE(generators.scene || generators.document);

  const auto move = std::get<CameraMotion>(
      parse_client_message(R"({"type":"move","forward":-0.5,"yaw":10,"roll":1e-3})", limits));
  EXPECT_EQ(move.forward, -0.5);
  EXPECT_EQ(move.yaw, 10);
  EXPECT_EQ(move.roll, 1e-3);
  EXPECT_EQ(move.right, 0);

  const auto settings = std::get<SessionSettings>(
      parse_client_message(R"({"type":"settings","width":64,"max_depth":0})", limits));
  EXPECT_EQ(settings.width, 64);
  EXPECT_EQ(settings.height, 0);  // absent: unchanged
  EXPECT_EQ(settings.max_depth, 0);
}

TEST(Protocol, NamesTheFieldOfABadMessage) {
  EXPECT_EQ(field_of_error("not json"), "");
  EXPECT_EQ(field_of_error("[1, 2]"), "");
  EXPECT_EQ(field_of_error(R"({"forward":1})"), "type");
  EXPECT_EQ(field_of_error(R"({"type":3})"), "type");
  EXPECT_EQ(field_of_error(R"({"type":"jump"})"), "type");
  EXPECT_EQ(field_of_error(R"({"type":"move","forward":"far"})"), "forward");
  EXPECT_EQ(field_of_error(R"({"type":"move","fwd":1})"), "fwd");
  EXPECT_EQ(field_of_error(R"({"type":"settings","width":15})"), "width");
  EXPECT_EQ(field_of_error(R"({"type":"settings","width":1921})"), "width");
  EXPECT_EQ(field_of_error(R"({"type":"settings","height":64.5})"), "height");
  EXPECT_EQ(field_of_error(R"({"type":"settings","max_depth":17})"), "max_depth");
  EXPECT_EQ(field_of_error(R"({"type":"open"})"), "scene");
  EXPECT_EQ(field_of_error(R"({"type":"open","scene":7})"), "scene");
  EXPECT_EQ(field_of_error(R"({"type":"open","scene":"a","document":{}})"), "document");
  EXPECT_EQ(field_of_error(R"({"type":"open","document":[]})"), "document");
  EXPECT_EQ(field_of_error(R"({"type":"open","generators":7})"), "generators");
  EXPECT_EQ(field_of_error(R"({"type":"open","scene":"a","generators":"1"})"), "generators");
}

// nlohmann throws out_of_range, not parse_error, for a number beyond double's range; it
// escaped parse_client_message and, on the daemon, ended the I/O thread (std::terminate).
TEST(Protocol, NumberOverflowIsInvalidJson) {
  try {
    parse_client_message(R"({"type":"move","forward":1e400})", ServiceLimits{});
    ADD_FAILURE() << "accepted";
  } catch (const ProtocolError& e) {
    EXPECT_EQ(e.field(), "");
    EXPECT_EQ(std::string(e.what()), "invalid JSON: number overflow parsing '1e400'");
  }
}

TEST(Protocol, MapsServiceErrorsToPathsInTheMessage) {
  const OpenRequest by_name{"nowhere", std::nullopt};
  const OpenRequest inline_document{std::nullopt, json::object()};
  const auto unknown = service_error(SceneError("scene: unknown bundled scene \"nowhere\""),
                                     &by_name);
  EXPECT_EQ(unknown.field(), "scene");
  EXPECT_STREQ(unknown.what(), "unknown bundled scene \"nowhere\"");
  EXPECT_EQ(service_error(SceneError("objects[2].radius: must be > 0"), &inline_document).field(),
            "document.objects[2].radius");
  EXPECT_EQ(service_error(SceneError("(root): must be an object"), &inline_document).field(),
            "document");
  const auto width = service_error(std::invalid_argument("width: must be in [16, 640]"), nullptr);
  EXPECT_EQ(width.field(), "width");
  EXPECT_STREQ(width.what(), "must be in [16, 640]");
  EXPECT_EQ(service_error(std::invalid_argument("no renderer: out of memory"), nullptr).field(), "");
}

TEST(Protocol, ServerMessagesMatchTheSchema) {
  expect_server_message_valid(hello_message(3, {"cornell-box", "furnace"}, ServiceLimits{},
                                            1 << 20, std::chrono::minutes(10)));
  expect_server_message_valid(
      scene_message({"Cornell box", "euclidean", "none", 512, 512, 5}));
  FrameInfo frame;
  frame.frame = 7;
  frame.spp = 1;
  frame.width = 64;
  frame.height = 48;
  frame.camera = Mat4::identity();
  const json unknown_error = json::parse(frame_message(frame));
  EXPECT_TRUE(unknown_error["error"].is_null());  // < 2 samples
  expect_server_message_valid(frame_message(frame));
  frame.error = 0.25;
  frame.camera.m[0][3] = 1.5;
  const json known_error = json::parse(frame_message(frame));
  EXPECT_EQ(known_error["error"], 0.25);
  ASSERT_EQ(known_error["camera"].size(), 16u);
  EXPECT_EQ(known_error["camera"][3], 1.5);  // row-major
  frame.non_finite_samples = 3;
  frame.truncated_geodesics = 5000000000;  // past 32 bits: counted over many passes
  const json counted = json::parse(frame_message(frame));
  EXPECT_EQ(counted["non_finite_samples"], 3);
  EXPECT_EQ(counted["truncated_geodesics"], 5000000000);
  expect_server_message_valid(frame_message(frame));
  expect_server_message_valid(error_message(ProtocolError("document.objects[0]", "bad \xff")));
}

TEST(Protocol, ClientExamplesMatchTheSchema) {
  for (const char* text : {R"({"type":"open","scene":"furnace"})",
                           R"({"type":"move","forward":0.5,"pitch":-3})",
                           R"({"type":"settings","width":64,"height":48,"max_depth":2})"})
    EXPECT_TRUE(test::ws_messages_schema().errors(json::parse(text), "/$defs/client_message").empty())
        << text;
  EXPECT_FALSE(test::ws_messages_schema()
                   .errors(json::parse(R"({"type":"settings","width":8})"), "/$defs/client_message")
                   .empty());
}

}  // namespace
}  // namespace geodesic::net
