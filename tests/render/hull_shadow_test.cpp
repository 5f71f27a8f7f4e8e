// Shadow segments skip the primitives on the scene's hull (render/prepare/triangle_list.h,
// list_hull_first): inside a closed room of six quads, a floor point's direct light from a
// point light against its closed form I rho / pi cos / d^2 with the light inside (five walls
// and the ceiling skipped), above a window in the ceiling (lit through it), and above the
// closed ceiling (dark: the ceiling, not on the hull, still casts its shadow).
#include <cmath>
#include <string>

#include "render/prepare/packed_scene.h"
#include "render_fixture.h"

namespace geodesic::test {
namespace {

const Vec3 kLight{0.05, 1.3, -0.02};  // above the ceiling at y = 1 (and its window)

std::string quad(const std::string& corner, const std::string& u, const std::string& v) {
  return R"({"type": "quad", "material": "white", "corner": [)" + corner + R"(], "edge_u": [)" +
         u + R"(], "edge_v": [)" + v + "]}";
}

// The room [-1, 1]^3, its ceiling whole or with a window [-0.1, 0.1]^2 about x = z = 0, a point
// light of intensity 2 at `light`, the camera at height 0 looking down at the floor point
// (x, -1, z).
Scene room(bool window, const Vec3& light, double x, double z) {
  std::string ceiling = window ? quad("-1, 1, -1", "2, 0, 0", "0, 0, 0.9") + "," +
                                     quad("-1, 1, 0.1", "2, 0, 0", "0, 0, 0.9") + "," +
                                     quad("-1, 1, -0.1", "0.9, 0, 0", "0, 0, 0.2") + "," +
                                     quad("0.1, 1, -0.1", "0.9, 0, 0", "0, 0, 0.2")
                               : quad("-1, 1, -1", "2, 0, 0", "0, 0, 2");
  const auto num = [](double v) { return std::to_string(v); };
  return scene_from_json(R"({"geometry": "euclidean",
    "camera": {"position": [)" + num(x) + ", 0, " + num(z) + R"(], "look_at": [)" + num(x) +
    ", -1, " + num(z) + R"(], "up": [0, 0, -1], "fov_y": 2},
    "materials": {"white": {"diffuse": 0.5}},
    "objects": [)" + quad("-1, -1, -1", "0, 0, 2", "2, 0, 0") + "," +
    quad("-1, -1, -1", "2, 0, 0", "0, 2, 0") + "," + quad("-1, -1, 1", "0, 2, 0", "2, 0, 0") + "," +
    quad("-1, -1, -1", "0, 2, 0", "0, 0, 2") + "," + quad("1, -1, -1", "0, 0, 2", "0, 2, 0") + "," +
    ceiling + R"(],
    "lights": [{"type": "point", "position": [)" + num(light.x) + ", " + num(light.y) + ", " +
    num(light.z) + R"(], "intensity": 2}],
    "render": {"width": 8, "height": 8, "max_depth": 0, "lighting": "physical", "ambient": 0}})");
}

// The floor's radiance at (x, -1, z) lit by the light: 0.5 / pi * 2 cos / d^2.
double lit_floor(const Vec3& light, double x, double z) {
  const Vec3 to_light = light - Vec3{x, -1, z};
  const double d = length(to_light);
  return 0.5 / M_PI * 2 * (to_light.y / d) / (d * d);
}

double floor_radiance(const Scene& scene) {
  Renderer renderer(device(), scene);
  renderer.add_samples(16);
  EXPECT_EQ(renderer.non_finite_samples(), 0u);
  return luminance_of(mean(renderer.image()));
}

TEST(HullShadows, ALightInsideTheRoomLightsTheFloorAsItsClosedForm) {
  const Vec3 light{0.2, 0.6, -0.1};
  const Scene scene = room(false, light, 0.7, 0.4);
  const PackedScene packed = pack_scene(scene);
  ASSERT_EQ(packed.cells.size(), 1u);
  EXPECT_EQ(packed.cells[0].listed_hull_pairs, 6u);  // all six walls: no shadow tests
  const double expected = lit_floor(light, 0.7, 0.4);
  EXPECT_NEAR(floor_radiance(scene), expected, 0.01 * expected);
}

TEST(HullShadows, ALightAboveTheClosedCeilingLeavesTheFloorDark) {
  const Scene scene = room(false, kLight, 0, 0);
  EXPECT_EQ(pack_scene(scene).cells[0].listed_hull_pairs, 5u);  // the ceiling is not skipped
  EXPECT_EQ(floor_radiance(scene), 0.0);
  EXPECT_EQ(floor_radiance(room(false, kLight, -0.9, 0.9)), 0.0);  // by a corner
}

TEST(HullShadows, ALightAboveAWindowLightsTheFloorThroughItAndNowhereElse) {
  EXPECT_EQ(pack_scene(room(true, kLight, 0, 0)).cells[0].listed_hull_pairs, 5u);
  // Below the light its closed form; (0.9, -1, -0.8) sees the light through the ceiling at
  // (0.16, 1, -0.12), beside the window.
  const double expected = lit_floor(kLight, 0.05, -0.02);
  EXPECT_NEAR(floor_radiance(room(true, kLight, 0.05, -0.02)), expected, 0.01 * expected);
  EXPECT_EQ(floor_radiance(room(true, kLight, 0.9, -0.8)), 0.0);
}

}  // namespace
}  // namespace geodesic::test
