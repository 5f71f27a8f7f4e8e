// The horosphere (server/scene/shapes/horosphere.cpp, shaders/primitives/shapes/horosphere.glsl),
// the first shape of the shape table (scene/shape.h). Its double twin against closed forms, and
// the rendered float GLSL against the same closed forms: from a point at distance d outside
// it, the horoball subtends an angular radius alpha with sin(alpha) = e^-d (in the upper
// half-space model the horoball {z >= 1} seen from height e^-d: the geodesic leaving at angle
// theta from the vertical rises to e^-d / sin(theta)), near the origin and 8 out; and the float
// GLSL against the twin, case by case, through the geometry probe.
#include <cmath>
#include <numbers>
#include <random>

#include "common/shape_kinds.h"
#include "geometry_probe.h"
#include "render_fixture.h"
#include "scene/scene_isometry.h"
#include "scene/shape.h"
#include "test_constants.h"

namespace geodesic::test {
namespace {


// Uniform numbers in [lo, hi) from a fixed seed.
class Uniform {
 public:
  explicit Uniform(unsigned seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }

 private:
  std::mt19937 engine_;
};

ShapeParams horosphere(const Vec3& direction, double distance) {
  ShapeParams s;
  s.a = std::exp(distance) * Vec4(normalize(direction), 1);
  return s;
}

// The camera at the origin looking down -z at a glowing horosphere at distance d along -z.
std::string facing_horosphere(double distance, int size, double fov) {
  return R"({"geometry": "hyperbolic",
    "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov_y": )" + std::to_string(fov) + R"(},
    "materials": {"glow": {"emission": 1}},
    "objects": [{"type": "horosphere", "direction": [0, 0, -1], "distance": )" +
         std::to_string(distance) + R"(, "material": "glow"}],
    "render": {"width": )" + std::to_string(size) + R"(, "height": )" + std::to_string(size) +
         R"(, "max_depth": 0}})";
}

TEST(Horosphere, TwinMeetsTheHorosphereOnlyInsideTheConeOfArcsinEToTheMinusD) {
  const ShapeKind& kind = shape_kind(SHAPE_HOROSPHERE);
  const double d = 1.3;
  const ShapeParams s = horosphere({0.3, -0.5, 0.8}, d);
  const Vec3 axis = normalize(Vec3{0.3, -0.5, 0.8});
  const double alpha = std::asin(std::exp(-d));
  Uniform random(7);
  for (int i = 0; i < 2000; ++i) {
    // Directions at angles up to 2 alpha from the axis, grazing ones included.
    const Vec3 u = normalize(Vec3{random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)});
    const double theta = random.uniform(0, 2 * alpha);
    const Vec3 side = normalize(u - dot(u, axis) * axis);
    const Vec3 dir = std::cos(theta) * axis + std::sin(theta) * side;
    const Vec4 p = model::origin(), v{dir, 0};
    const double t = kind.intersect(kH3, s, p, v, 0, 1e30);
    if (std::abs(theta - alpha) < 1e-9) continue;
    ASSERT_EQ(std::isfinite(t), theta < alpha) << "theta " << theta << " alpha " << alpha;
    if (!std::isfinite(t)) continue;
    const Vec4 q = model::geodesic_point(kH3, p, v, t);
    EXPECT_NEAR(model::inner(kH3, q, s.a), -1, 1e-12 * std::exp(d + t));  // on it
    const Vec4 n = kind.normal(kH3, s, q);
    EXPECT_NEAR(model::inner(kH3, n, n), 1, 1e-12);
    EXPECT_NEAR(model::inner(kH3, n, q), 0, 1e-12);
    // Entering from outside: the normal faces the ray, and the horoball lies ahead.
    EXPECT_LT(model::inner(kH3, n, model::geodesic_tangent(kH3, p, v, t)), 0);
  }
  // Straight along the axis the distance is d.
  EXPECT_NEAR(kind.intersect(kH3, s, model::origin(), Vec4{axis, 0}, 0, 1e30), d, 1e-12);
  // From inside the horoball every geodesic but the one into the ideal point leaves it, at
  // the distance back along the axis (d < 0: the origin is inside, -d from its surface).
  const ShapeParams around = horosphere({0, 0, 1}, -0.7);
  EXPECT_NEAR(kind.intersect(kH3, around, model::origin(), Vec4{0, 0, -1, 0}, 0, 1e30), 0.7, 1e-12);
  for (int i = 0; i < 200; ++i) {
    const Vec3 dir = normalize(Vec3{random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 0.99)});
    EXPECT_TRUE(std::isfinite(kind.intersect(kH3, around, model::origin(), Vec4{dir, 0}, 0, 1e30)));
  }
  EXPECT_FALSE(std::isfinite(kind.intersect(kH3, around, model::origin(), Vec4{0, 0, 1, 0}, 0, 1e30)));
}

TEST(Horosphere, ChartBoxHoldsTheHoroballInTheKleinChart) {
  const ShapeKind& kind = shape_kind(SHAPE_HOROSPHERE);
  Uniform random(3);
  for (const double d : {-2.0, 0.0, 0.4, 3.0}) {
    const Vec3 n = normalize(Vec3{random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)});
    const ShapeParams s = horosphere(n, d);
    const auto box = kind.chart_box(kH3, s);
    ASSERT_TRUE(box);
    ChartBox seen{{1, 1, 1}, {-1, -1, -1}};
    for (int i = 0; i < 20000; ++i) {  // points of the horosphere: rays from its nearest point
      const Vec4 p = model::exp_origin(kH3, d * n);
      const Vec3 u = normalize(Vec3{random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)});
      const Vec4 v = model::normalize_tangent(kH3, p, Vec4{u, 0});
      const double t = kind.intersect(kH3, s, p, v, 1e-9, 1e30);
      if (!std::isfinite(t) || t > 30) continue;
      const Vec3 x = model::chart(kH3, model::geodesic_point(kH3, p, v, t));
      for (int j = 0; j < 3; ++j) {
        EXPECT_GE(x[j], box->lo[j] - 1e-9);
        EXPECT_LE(x[j], box->hi[j] + 1e-9);
      }
      seen.lo = {std::min(seen.lo.x, x.x), std::min(seen.lo.y, x.y), std::min(seen.lo.z, x.z)};
      seen.hi = {std::max(seen.hi.x, x.x), std::max(seen.hi.y, x.y), std::max(seen.hi.z, x.z)};
    }
    for (int j = 0; j < 3; ++j) {  // and it is tight: the points found reach its sides
      EXPECT_NEAR(seen.lo[j], box->lo[j], 0.02) << "d " << d;
      EXPECT_NEAR(seen.hi[j], box->hi[j], 0.02) << "d " << d;
    }
  }
}

// The float GLSL (through the shape table, as the renderer calls it) against the double twin on
// the same float inputs: rays from up to 1.5 from the origin at horospheres within 2 of it,
// aimed at them (hitting, grazing, from inside) or anywhere. Hit or miss agree except within
// 1e-3 of tangency (1 - <m, m>, intersect's discriminant), where a float rounding decides; the
// arc length agrees to 1e-5 (1 + t) (worst seen 1.9e-6) and the normal at the hit point q to
// 1e-6 w^2 |q| (worst 1.9e-7: q rounded to float lies u w^2 off the model).
TEST(Horosphere, FloatIntersectionAndNormalMatchTheDoubleTwin) {
  const ShapeKind& kind = shape_kind(SHAPE_HOROSPHERE);
  ProbeCaseMaker maker(kH3, 21);
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 6000; ++i) {
    ProbeCase c = maker.make();
    const Vec4 p = sample.point(1.5);
    const ShapeParams s = horosphere(sample.unit3(), sample.uniform(-2, 2));
    Vec4 v = sample.tangent(p);
    if (i % 3 == 0) {  // aimed near its ideal point, off by up to 0.8 sideways
      const Vec4 towards = model::geodesic_direction(kH3, p, model::normalize_point(kH3, s.a));
      v = model::normalize_tangent(kH3, p, towards + sample.uniform(0, 0.8) * sample.tangent(p));
    }
    c.point = f4(p);
    c.tangent = f4(v);
    c.shape_a = f4(s.a);
    c.shape_size = {0, kFar, 0, 0};
    c.shape_kind = {SHAPE_HOROSPHERE, 0, 0, 0};
    cases.push_back(c);
  }
  // q: where the double twin meets the surface (on the float inputs), for the normal.
  std::vector<double> hit(cases.size());
  for (size_t i = 0; i < cases.size(); ++i) {
    ProbeCase& c = cases[i];
    ShapeParams s;
    s.a = v4(c.shape_a);
    hit[i] = kind.intersect(kH3, s, v4(c.point), v4(c.tangent), 0, 1e30);
    c.target = std::isfinite(hit[i]) ? f4(model::geodesic_point(kH3, v4(c.point), v4(c.tangent), hit[i]))
                                     : f4(model::origin());
  }
  const auto results = run_probe(kH3, cases);
  int hits = 0, borderline = 0;
  double worst_t = 0, worst_n = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const Vec4 p = v4(cases[i].point), v = v4(cases[i].tangent), l = v4(cases[i].shape_a);
    const double alpha = -model::inner(kH3, p, l), beta = model::inner(kH3, v, l);
    const Vec4 m = l - alpha * p - beta * v;
    if (std::abs(1 - model::inner(kH3, m, m)) < 1e-3) {  // grazing: either answer is right
      ++borderline;
      continue;
    }
    const double t = results[i].shape_hit[0];
    ASSERT_EQ(std::isfinite(hit[i]), t < kFar) << "case " << i << " twin " << hit[i] << " glsl " << t;
    if (!std::isfinite(hit[i])) continue;
    ++hits;
    worst_t = std::max(worst_t, std::abs(t - hit[i]) / (1 + hit[i]));
    ShapeParams s;
    s.a = l;
    const Vec4 q = v4(cases[i].target);
    const Vec4 n = kind.normal(kH3, s, q);
    // Relative to |q|, the normal's float error grows with how far off the model the rounded
    // q lies, u <q, q> ~ u w^2: held to that.
    const double dn = max_abs(v4(results[i].shape_normal) - n) / max_abs(q) / (q.w * q.w);
    worst_n = std::max(worst_n, dn);
  }
  EXPECT_GT(hits, 2000);
  EXPECT_LT(borderline, 100);
  EXPECT_LT(worst_t, 1e-5);
  EXPECT_LT(worst_n, 1e-6);
  std::printf("horosphere probe: %d hits, %d grazing skipped, worst |dt|/(1+t) %.2e, normal %.2e w^2\n",
              hits, borderline, worst_t, worst_n);
}

// Covered pixels of the centre row against the pinhole projection of alpha.
double covered_row(const Image& image) {
  double covered = 0;
  for (int x = 0; x < image.width; ++x) covered += image.at(x, image.height / 2, 0);
  return covered;
}

TEST(Horosphere, AngularSizeIsArcsinEToTheMinusDNearTheOriginAndEightOut) {
  constexpr int kSize = 101;
  constexpr double kFov = 60;
  const double tan_half = std::tan(kFov * std::numbers::pi / 360);
  const Mat4 far = model::translation(kH3, Vec3{6, -4, 3});  // 7.8 from the origin
  for (const double d : {0.8, 1.5, 3.0}) {  // alpha 26.7, 12.9 and 2.9 degrees
    const Scene scene = scene_from_json(facing_horosphere(d, kSize, kFov));
    const double expected = std::tan(std::asin(std::exp(-d))) / tan_half * kSize;
    for (const BackendKind backend : {BackendKind::RayQuery, BackendKind::RayTracingPipeline})
      EXPECT_NEAR(covered_row(render(scene, 16, backend)), expected, 1.0)
          << "d " << d << (backend == BackendKind::RayQuery ? " ray query" : " pipeline");
    EXPECT_NEAR(covered_row(render(moved_scene(scene, far), 16)), expected, 1.0) << "d " << d << " far out";
  }
}

TEST(Horosphere, FromInsideTheHoroballEveryDirectionMeetsIt) {
  const Image image = render(scene_from_json(facing_horosphere(-0.5, 16, 120)), 4);
  for (float value : image.rgb) ASSERT_EQ(value, 1.0f);
}

// Inside a glowing diffuse horoball (Le = 1, albedo 0.5) paths bounce along the horosphere,
// which runs off without end; past the float horizon (primitives/shape_table.glsl) they stop
// instead of losing themselves in NaN. Every pixel sees Le and some reflected light. BSDF
// sampling alone has no variance here (every bounce meets the horosphere and keeps half), so
// each pixel lies in [1, 2]; with the horosphere sampled as a light (MIS) the image's mean is
// the same within 1 %.
TEST(Horosphere, PathsBouncingInsideTheHoroballStayFinite) {
  std::string text = facing_horosphere(-1.5, 24, 120);
  text.replace(text.find(R"({"emission": 1})"), 15, R"({"emission": 1, "diffuse": 0.5})");
  text.replace(text.find(R"("max_depth": 0)"), 14, R"("max_depth": 32)");
  Scene scene = scene_from_json(text);
  scene.render.russian_roulette = false;
  double means[2];
  for (LightSampling sampling : {LightSampling::Bsdf, LightSampling::Mis}) {
    scene.render.light_sampling = sampling;
    Renderer renderer(device(), scene);
    renderer.add_samples(64);
    EXPECT_EQ(renderer.non_finite_samples(), 0u);
    const Image image = renderer.image();
    for (float value : image.rgb) {
      ASSERT_TRUE(std::isfinite(value));
      if (sampling != LightSampling::Bsdf) continue;
      ASSERT_GE(value, 1.0f);
      ASSERT_LE(value, 2.0f);  // Le / (1 - albedo): what a closed room would reach
    }
    means[sampling == LightSampling::Bsdf ? 0 : 1] = luminance_of(mean(image));
  }
  EXPECT_NEAR(means[1], means[0], 0.01 * means[0]);
}

TEST(Horosphere, LitByASphereLightInAClosedManifoldWithoutNonFiniteSamples) {
  Scene scene = load_scene_file(source_path("scenes/seifert-weber.json"));
  scene.render.width = scene.render.height = 24;
  scene.render.max_depth = 32;
  scene.shapes.push_back({SHAPE_HOROSPHERE, horosphere({0.2, 0.1, -1}, 0.15), 0});
  Renderer renderer(device(), scene);
  renderer.add_samples(2);
  EXPECT_EQ(renderer.non_finite_samples(), 0u);
  // It is in the picture: the same scene without it differs.
  Scene without = scene;
  without.shapes.clear();
  EXPECT_GT(rms_difference(renderer.image(), render(without, 2)), 1e-3);
}

TEST(Horosphere, RefusedOutsideHyperbolicSpaceAndWithoutADirection) {
  const auto error_of = [](const std::string& text) {
    try {
      scene_from_json(text);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(error_of(R"({"geometry": "euclidean", "camera": {"position": [0, 0, 0]}, "materials": {"m": {}}, "objects": [
      {"type": "horosphere", "direction": [0, 0, 1], "distance": 1, "material": "m"}]})"),
            "objects[0].type: a horosphere exists only in hyperbolic space");
  EXPECT_EQ(error_of(R"({"geometry": "hyperbolic", "camera": {"position": [0, 0, 0]}, "materials": {"m": {}}, "objects": [
      {"type": "horosphere", "direction": [0, 0, 0], "distance": 1, "material": "m"}]})"),
            "objects[0].direction: must not be zero");
  EXPECT_EQ(error_of(R"({"geometry": "hyperbolic", "camera": {"position": [0, 0, 0]}, "materials": {"m": {}}, "objects": [
      {"type": "horosphere", "direction": [0, 0, 1], "distance": 31, "material": "m"}]})"),
            "objects[0].distance: must be within [-30, 30]");
  EXPECT_EQ(error_of(R"({"geometry": "hyperbolic", "camera": {"position": [0, 0, 0]}, "materials": {"m": {}}, "objects": [
      {"type": "horosphere", "direction": [0, 0, 1], "distance": 1, "radius": 2, "material": "m"}]})"),
            "objects[0]: unknown field \"radius\"");
}

}  // namespace
}  // namespace geodesic::test
