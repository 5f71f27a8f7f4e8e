// Walking far in plain H3 over the WebSocket (docs/numerics.md, "Far from the origin"): each
// move that takes the camera more than 2 units from its renderer's frame has a renderer built
// at the camera on the preparation pool; the frames go on at the walked pose, with no
// non-finite sample and no error, 9 units out.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "daemon_fixture.h"
#include "geometry/model.h"
#include "render/prepare/image_io.h"

namespace geodesic::test {
namespace {

using nlohmann::json;

TEST(FarWalk, AWalkNineUnitsOutInH3KeepsItsFramesAndItsPose) {
  Daemon daemon;
  WsClient client(daemon.port());
  client.read_until("hello");
  client.read_scene();
  // Spheres every 3 units along the walk, 0.8 to its side, so there is something beside the
  // camera all along (exponential coordinates of points beside a geodesic fan out: computed).
  // Radius 0.6: the one 3 units ahead spans 3 pixels of the 24 rows, so its centre pixel is
  // covered whatever the samples (at 0.3 it spanned 1.4 and its brightest pixel varied).
  const auto k = GeometryKind::Hyperbolic;
  json objects = json::array();
  for (int i = 0; i <= 4; ++i) {
    const Vec3 c = model::log_origin(k, model::translation(k, {0, 0, -3.0 * i}) *
                                            model::exp_origin(k, {0.8, 0, 0}));
    objects.push_back({{"type", "sphere"}, {"material", "m"}, {"center", {c.x, c.y, c.z}},
                       {"radius", 0.6}});
  }
  client.send({{"type", "open"},
               {"document",
                {{"geometry", "hyperbolic"},
                 {"camera", {{"position", {0, 0, 0}}, {"look_at", {0, 0, -1}}}},
                 {"materials", {{"m", {{"diffuse", 0.5}, {"emission", 0.5}}}}},
                 {"objects", objects}}}});
  client.read_scene();
  client.send({{"type", "settings"}, {"width", 32}, {"height", 24}});
  for (int step = 0; step < 6; ++step) client.send({{"type", "move"}, {"forward", 1.5}});
  // The camera is 9 units along -z from the origin: its pose's w row ends in cosh 9.
  const auto frame = client.read_frame_where(
      [](const json& f) {
        return !f["moving"].get<bool>() && f["spp"] >= 4 &&
               std::abs(f["camera"][15].get<double>() - std::cosh(9.0)) < 1e-6 * std::cosh(9.0);
      });
  EXPECT_EQ(frame.info["non_finite_samples"], 0);
  EXPECT_NEAR(frame.info["camera"][11].get<double>(), -std::sinh(9.0), 1e-6 * std::sinh(9.0));
  // The sphere 3 units ahead shows (emission 0.5; black without the walk's new renderer).
  const auto path = std::filesystem::temp_directory_path() /
                    ("far-walk-" + std::to_string(::getpid()) + ".jpg");
  std::ofstream(path, std::ios::binary).write(frame.jpeg.data(), std::streamsize(frame.jpeg.size()));
  const Image image = read_image(path);
  std::filesystem::remove(path);
  float brightest = 0;
  for (float v : image.rgb) brightest = std::max(brightest, v);
  EXPECT_GT(brightest, 0.3f);
}

}  // namespace
}  // namespace geodesic::test
