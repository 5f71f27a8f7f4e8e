// Exposure in a WebSocket session (docs/protocol.md, `settings.exposure`): a new exposure
// re-encodes the last frame without restarting the accumulation, the JPEG's values follow
// 2^stops, also the stops "auto" chose, and bad values are named.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include <unistd.h>

#include <gtest/gtest.h>

#include "daemon_fixture.h"
#include "render/prepare/exposure.h"
#include "render/prepare/image_io.h"

namespace geodesic::test {
namespace {

using nlohmann::json;

Image decode(const WsClient::Frame& frame) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("exposure-session-" + std::to_string(::getpid()) + ".jpg");
  std::ofstream(path, std::ios::binary).write(frame.jpeg.data(), std::streamsize(frame.jpeg.size()));
  Image image = read_image(path);
  std::filesystem::remove(path);
  return image;
}

TEST(ExposureSession, ANewExposureReencodesTheAccumulationAndItsJpegFollowsTwoToTheStops) {
  Daemon daemon;
  WsClient client(daemon.port());
  client.read_until("hello");
  const json scene = client.read_scene();
  EXPECT_EQ(scene["exposure"], 0.0);
  client.send({{"type", "settings"}, {"width", 64}, {"height", 48}});
  const auto plain = client.read_frame_where([](const json& f) {
    return f["width"] == 64 && f["spp"] >= 16 && f["exposure"] == 0.0;
  });

  client.send({{"type", "settings"}, {"exposure", 2}});
  const auto bright = client.read_frame_where([](const json& f) { return f["exposure"] == 2.0; });
  // The same accumulation, not a new one: as many samples or more, and the same reset time.
  EXPECT_GE(bright.info["spp"].get<int>(), plain.info["spp"].get<int>());
  EXPECT_GE(bright.info["elapsed"].get<double>(), plain.info["elapsed"].get<double>());
  // Values below a quarter (not clipped at 4x) come out 4 times brighter, within the JPEG's
  // and the extra samples' noise.
  const Image a = decode(plain), b = decode(bright);
  double sum_a = 0, sum_b = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i)
    if (a.rgb[i] > 0.01f && a.rgb[i] < 0.2f) {
      sum_a += a.rgb[i];
      sum_b += b.rgb[i];
    }
  ASSERT_GT(sum_a, 0);
  EXPECT_NEAR(sum_b / sum_a, 4.0, 0.4);

  client.send({{"type", "settings"}, {"exposure", "auto"}});
  const auto automatic = client.read_frame_where([](const json& f) { return f["exposure"] != 2.0; });
  const double stops = automatic.info["exposure"];
  EXPECT_GT(stops, -kMaxExposureStops);
  EXPECT_LT(stops, kMaxExposureStops);
  // Its JPEG's values are the plain one's times 2^stops where neither clips (the linear
  // image it was computed from stays on the server: render/prepare/exposure.h's closed form is checked
  // in the unit and CLI tests).
  const Image shown = decode(automatic);
  const double gain = std::exp2(stops);
  double plain_sum = 0, shown_sum = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i)
    if (a.rgb[i] > 0.01f && a.rgb[i] * gain < 0.8) {
      plain_sum += a.rgb[i];
      shown_sum += shown.rgb[i];
    }
  ASSERT_GT(plain_sum, 0);
  EXPECT_NEAR(shown_sum / plain_sum / gain, 1.0, 0.1) << "auto: " << stops << " stops";

  client.send({{"type", "settings"}, {"exposure", "bright"}});
  const json error = client.read_until("error");
  EXPECT_EQ(error["field"], "exposure");
  EXPECT_EQ(error["message"], "must be a number of stops in [-20, 20] or \"auto\"");
  client.send({{"type", "settings"}, {"exposure", 25}});
  EXPECT_EQ(client.read_until("error")["field"], "exposure");
}

}  // namespace
}  // namespace geodesic::test
