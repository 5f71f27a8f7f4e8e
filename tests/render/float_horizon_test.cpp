// The float horizon of plain H3 (primitives/surface.glsl, docs/numerics.md): shading a hit d
// from the camera's frame cancels products of size e^2d, and from d = 8 a sphere's normal comes
// out zero, a NaN sample. A hit beyond d = 7 is seen with its emission, and no path goes on
// from it; nearer, paths go on as anywhere. A camera with a 0.005-degree view sees nothing but
// one sphere, its every hit point the same distance out.
#include "geometry/model.h"
#include "render_fixture.h"

namespace geodesic::test {
namespace {

constexpr int kViewSize = 8;
constexpr uint32_t kViewSpp = 1024;

const Vec3 kLampOffset{0, 0.6, 1.4};  // in the ball's frame: nearer the camera, above the view
constexpr double kBallRadius = 0.6, kBallEmission = 0.25, kLampRadius = 0.3, kLampEmission = 4;

// A diffuse ball (albedo 0.5, emission 0.25) of radius 0.6 whose centre is `centre` out along
// the view, lit by a sphere light of radius 0.3 (outside the view); the view lies inside the
// ball's disc, about its point nearest the camera.
Scene far_sphere(double centre) {
  const auto k = GeometryKind::Hyperbolic;
  const Mat4 there = model::translation(k, {0, 0, -centre});
  const Vec3 ball = model::log_origin(k, there * model::origin());
  const Vec3 lamp = model::log_origin(k, there * model::exp_origin(k, kLampOffset));
  const nlohmann::json document = {
      {"geometry", "hyperbolic"},
      {"camera", {{"position", {0, 0, 0}}, {"look_at", {0, 0, -1}}, {"fov_y", 0.005}}},
      {"materials",
       {{"ball", {{"diffuse", 0.5}, {"emission", kBallEmission}}},
        {"lamp", {{"emission", kLampEmission}}}}},
      {"objects",
       {{{"type", "sphere"}, {"material", "ball"}, {"center", {ball.x, ball.y, ball.z}},
         {"radius", kBallRadius}},
        {{"type", "sphere"}, {"material", "lamp"}, {"center", {lamp.x, lamp.y, lamp.z}},
         {"radius", kLampRadius}}}},
      {"render", {{"width", kViewSize}, {"height", kViewSize}, {"max_depth", 2}}}};
  return scene_from_json(document.dump());
}

struct FarRender {
  Image image;
  uint32_t non_finite = 0;
  double rays_per_path = 0;
};

FarRender render_far(double centre) {
  Renderer renderer(device(), far_sphere(centre));
  renderer.add_samples(kViewSpp);
  return {renderer.image(), renderer.non_finite_samples(),
          double(renderer.trace_counters().traced_rays) /
              (double(kViewSize) * kViewSize * kViewSpp)};
}

// Hits 8.9 out (the float-only shading gave a zero normal at a third of them, each a NaN
// sample): every pixel is the sphere's emission, exactly, and every path is its camera ray alone.
TEST(FloatHorizon, ASphereHitBeyondItShowsItsEmissionAndNoPathGoesOn) {
  const FarRender far = render_far(9.5);
  EXPECT_EQ(far.non_finite, 0u);
  EXPECT_EQ(far.rays_per_path, 1.0);
  for (float value : far.image.rgb) ASSERT_EQ(value, float(kBallEmission));
}

// Hits 5.9 out, inside the horizon: paths go on (a shadow ray and a bounce at least), no
// sample is lost, and the lamp lights the ball as it would at the origin: its cap lies wholly
// above the ball's horizon at the point seen (45 degrees off the normal, 15 wide), so the
// irradiance is E = pi Le sin^2(alpha) cos(theta), sin^2(alpha) = A(r) / A(d); the pixel is
// 0.25 + 0.5 E / pi: the 64 pixels' mean within 2 % of the lamp's part (they see one point).
TEST(FloatHorizon, ASphereHitInsideItIsShadedAndLit) {
  const auto k = GeometryKind::Hyperbolic;
  const Vec4 seen = model::exp_origin(k, {0, 0, kBallRadius});  // in the ball's frame
  const Vec4 lamp = model::exp_origin(k, kLampOffset);
  const double d = model::geodesic_distance(k, seen, lamp);
  const double cos_theta = model::inner(k, model::geodesic_direction(k, seen, lamp),
                                        model::sphere_normal(k, model::origin(), seen));
  const double lit = 0.5 * kLampEmission * model::sphere_area_factor(k, kLampRadius) /
                     model::sphere_area_factor(k, d) * cos_theta;
  const FarRender near = render_far(6.5);
  EXPECT_EQ(near.non_finite, 0u);
  EXPECT_GT(near.rays_per_path, 2.0);
  EXPECT_NEAR(mean(near.image).g, kBallEmission + lit, 0.02 * lit);
}

}  // namespace
}  // namespace geodesic::test
