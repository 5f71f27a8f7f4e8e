// The float GLSL geometry, sampling and random-number routines held against their double
// C++ twins in server/geometry/, run on the device through shaders/probes/geometry_probe.comp.
// Inputs are rounded to float first and the reference reads them back, so every difference
// is the shader's own float arithmetic.
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "geometry/euclidean.h"
#include "geometry/random.h"
#include "geometry/sampling.h"
#include "probe_runner.h"
#include "render_fixture.h"

namespace geodesic::test {
namespace {

using F4 = std::array<float, 4>;

// std430 twins of the structs in geometry_probe.comp.
struct ProbeCase {
  std::array<float, 16> pose;
  F4 origin, direction, sphere, target, normal, camera_direction, colour, uv;
  std::array<uint32_t, 4> rng;
};
static_assert(sizeof(ProbeCase) == 208);

struct ProbeResult {
  F4 scalars, point, towards, reflected, offset, camera_origin, camera_direction, tangent,
      bitangent, cosine_sample;
  std::array<uint32_t, 4> hashes;
  F4 draws;
};
static_assert(sizeof(ProbeResult) == 192);

// Twice float's unit round-off: slack for Vulkan's 2-3 ulp division and square root.
constexpr double kEps = FLT_EPSILON;
constexpr float kFar = 1e30f;

Vec3 vec(const F4& f) { return {f[0], f[1], f[2]}; }
F4 f4(const Vec3& v, double w = 0) { return {float(v.x), float(v.y), float(v.z), float(w)}; }
double max_abs(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

Mat4 from_glsl(const std::array<float, 16>& column_major) {
  Mat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m.m[r][c] = column_major[c * 4 + r];
  return m;
}

std::vector<ProbeResult> run_probe(const std::vector<ProbeCase>& cases) {
  ProbeRunner runner(device(), "geometry_probe.comp");
  return runner.run<ProbeResult>(cases);
}

// Random inputs for every routine; each test overrides the fields it studies.
class CaseMaker {
 public:
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(gen_);
  }
  Vec3 box(double half) {
    return {uniform(-half, half), uniform(-half, half), uniform(-half, half)};
  }
  Vec3 unit() {
    std::normal_distribution<double> g;
    return normalize(Vec3{g(gen_), g(gen_), g(gen_)});
  }
  // A unit vector perpendicular to the unit vector d.
  Vec3 perpendicular(const Vec3& d) { return normalize(cross(d, unit())); }

  // A random rigid motion: a right-handed frame as the rotation's columns, then a translation.
  Mat4 pose() {
    const Vec3 z = unit();
    const TangentFrame frame = orthonormal_basis(z);
    const Vec3 columns[4] = {frame.tangent, frame.bitangent, z, box(100)};
    Mat4 m = Mat4::identity();
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 3; ++row) m.m[row][col] = columns[col][row];
    return m;
  }

  ProbeCase make() {
    ProbeCase c{};
    c.pose = pose().to_glsl();
    c.origin = f4(box(10), 0.0);
    c.direction = f4(unit(), kFar);
    c.sphere = f4(box(10), uniform(0.1, 3));
    c.target = f4(box(10), uniform(0, 20));
    c.normal = f4(unit());
    c.camera_direction = f4({uniform(-1, 1), uniform(-1, 1), -1});
    c.colour = f4({uniform(0, 10), uniform(0, 10), uniform(0, 10)});
    c.uv = {float(uniform(0, 1)), float(uniform(0, 1)), 0, 0};
    for (auto& word : c.rng) word = uint32_t(gen_());
    return c;
  }

  // A ray from `origin` passing the sphere's centre at distance `impact` (< |center - origin|).
  void aim(ProbeCase& c, const Vec3& origin, const Vec3& center, double radius, double impact) {
    const Vec3 towards = normalize(center - origin);
    const double sin_tilt = impact / length(center - origin);
    c.origin = f4(origin, 0.0);
    const Vec3 d = std::sqrt(1 - sin_tilt * sin_tilt) * towards + sin_tilt * perpendicular(towards);
    c.direction = f4(d, kFar);
    c.sphere = f4(center, radius);
  }

 private:
  std::mt19937_64 gen_{20240611};
};

// What float can achieve for intersectSphere on one case: the standard model
// |fl(x op y) - x op y| <= u |x op y| (u = kEps) carried through the shader's steps, with
// F = |o - c| and l the closest-approach vector (the inputs are exact floats):
//   f = o - c        |df| <= u F            b = -f.d      |db| <= 4u F
//   l = f + b d      |dl| <= 6u F + u|l|    disc = r^2 - l.l
//   |ddisc| <= u (12 F|l| + 5|l|^2 + r^2 + |disc|)
//   s = sqrt(disc)   |ds| <= 2 ddisc / (sqrt|disc| + sqrt ddisc)   (also for disc near 0)
//   q = b +- s       |dq| <= 4u F + ds + u|q|
//   c = f.f - r^2    |dc| <= u (5F^2 + r^2 + |c|)
//   t0 = c/q, t1 = q |dt| <= dc/|q| + dq + u|q|   (|c/q| <= |q|)
// Far spheres are limited by l: it is a difference of two vectors of length ~F.
struct SphereTolerance {
  double disc = 0;
  double t = 0;
};

SphereTolerance sphere_tolerance(const ProbeCase& c, const euclidean::SphereRoots& roots) {
  const double u = kEps, r = c.sphere[3], f = length(vec(c.origin) - vec(c.sphere));
  const double l = std::sqrt(std::max(0.0, r * r - roots.disc));
  SphereTolerance tol;
  tol.disc = u * (12 * f * l + 5 * l * l + r * r + std::abs(roots.disc));
  if (roots.disc < 0) return tol;
  // The shader's q is the root of larger magnitude, and c is the product of the roots.
  const double q = std::max(std::abs(roots.t0), std::abs(roots.t1)), cc = roots.t0 * roots.t1;
  const double ds = 2 * tol.disc / (std::sqrt(roots.disc) + std::sqrt(tol.disc));
  const double dq = 4 * u * f + ds + u * q;
  tol.t = u * (5 * f * f + r * r + std::abs(cc)) / q + dq + u * q;
  return tol;
}

struct SphereStats {
  int hits = 0;
  int band_disagreements = 0;  // hit/miss or root choice differs inside the error band
  double max_relative_error = 0;
  double max_error_in_ulps_of_distance = 0;  // in units of ulp(float(F))
};

// intersectSphere's result against the reference. Hit/miss (or which root) may differ only
// where the decision lies inside the error band: the discriminant's sign, or a root at tMin/tMax.
::testing::AssertionResult sphere_agrees(const ProbeCase& c, float glsl, SphereStats& stats) {
  const Vec3 o = vec(c.origin), d = vec(c.direction), center = vec(c.sphere);
  const double r = c.sphere[3], t_min = c.origin[3], t_max = c.direction[3];
  const auto roots = euclidean::sphere_roots(o, d, center, r);
  const auto ref = euclidean::intersect_sphere(o, d, center, r, t_min, t_max);
  const SphereTolerance tol = sphere_tolerance(c, roots);
  const bool glsl_hit = glsl != -1.0f;
  if (glsl_hit && ref) {
    const double error = std::abs(glsl - *ref);
    const float distance = float(length(o - center));
    const double ulp = std::nextafter(distance, kFar) - distance;
    if (error <= tol.t) {
      ++stats.hits;
      stats.max_relative_error = std::max(stats.max_relative_error, error / *ref);
      stats.max_error_in_ulps_of_distance =
          std::max(stats.max_error_in_ulps_of_distance, error / ulp);
      return ::testing::AssertionSuccess();
    }
  } else if (glsl_hit == ref.has_value()) {
    return ::testing::AssertionSuccess();
  }
  const auto near = [&](double t, double bound) { return std::abs(t - bound) <= tol.t; };
  const bool in_band = std::abs(roots.disc) <= tol.disc ||
                       (roots.disc >= 0 && (near(roots.t0, t_min) || near(roots.t1, t_min) ||
                                            near(roots.t0, t_max) || near(roots.t1, t_max)));
  if (in_band) {
    ++stats.band_disagreements;
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "glsl " << glsl << " vs reference " << (ref ? *ref : -1.0) << " (disc " << roots.disc
         << " +- " << tol.disc << ", t tolerance " << tol.t << ", roots " << roots.t0 << ", "
         << roots.t1 << ")";
}

SphereStats check_spheres(const std::vector<ProbeCase>& cases) {
  const auto results = run_probe(cases);
  SphereStats stats;
  for (size_t i = 0; i < cases.size(); ++i)
    EXPECT_TRUE(sphere_agrees(cases[i], results[i].scalars[0], stats)) << "case " << i;
  return stats;
}

TEST(GlslReference, RandomNumbersAreBitExact) {
  CaseMaker maker;
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 4096; ++i) cases.push_back(maker.make());
  for (uint32_t edge : {0u, 1u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu}) {
    ProbeCase c = maker.make();
    c.rng = {edge, edge, edge, edge};
    cases.push_back(c);
  }
  const auto results = run_probe(cases);
  for (size_t i = 0; i < cases.size(); ++i) {
    const auto& in = cases[i].rng;
    const auto& out = results[i];
    ASSERT_EQ(out.hashes[0], pcg_hash(in[3])) << "case " << i;
    uint32_t state = rng_seed(in[0], in[1], in[2]);
    ASSERT_EQ(out.hashes[1], state) << "case " << i;
    for (int k = 0; k < 4; ++k) ASSERT_EQ(double(out.draws[k]), rng_next(state)) << "case " << i;
    ASSERT_EQ(out.hashes[2], state) << "case " << i;
  }
}

// Unit vectors within 1e-6; points and scalars within a few eps of their operands' size.
TEST(GlslReference, GeodesicHelpersMatchToFloatPrecision) {
  CaseMaker maker;
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 4096; ++i) {
    ProbeCase c = maker.make();
    if (i % 4 == 0) c.origin = f4(maker.box(1e4));  // far from the origin: offsets scale up
    cases.push_back(c);
  }
  const auto results = run_probe(cases);
  for (size_t i = 0; i < cases.size(); ++i) {
    const ProbeCase& c = cases[i];
    const ProbeResult& g = results[i];
    const Vec3 o = vec(c.origin), d = vec(c.direction), n = vec(c.normal), to = vec(c.target);
    const double t = c.target[3];
    SCOPED_TRACE("case " + std::to_string(i));

    EXPECT_LE(length(vec(g.point) - euclidean::geodesic_point({o, d}, t)),
              4 * kEps * (length(o) + t));
    const double distance = euclidean::geodesic_distance(o, to);
    EXPECT_NEAR(g.scalars[1], distance, 4 * kEps * distance);
    EXPECT_LE(max_abs(vec(g.towards) - euclidean::geodesic_direction(o, to)), 1e-6);
    EXPECT_NEAR(g.scalars[2], euclidean::metric_dot(o, d, n), 4 * kEps);
    EXPECT_LE(max_abs(vec(g.reflected) - euclidean::reflect_direction(o, d, n)), 1e-6);
    EXPECT_LE(max_abs(vec(g.offset) - euclidean::offset_from_surface(o, n)),
              4 * kEps * (1 + max_abs(o)));

    const euclidean::Ray camera = euclidean::camera_ray(from_glsl(c.pose), vec(c.camera_direction));
    EXPECT_LE(max_abs(vec(g.camera_origin) - camera.origin), kEps * max_abs(camera.origin));
    EXPECT_LE(max_abs(vec(g.camera_direction) - camera.direction), 1e-6);
  }
}

TEST(GlslReference, SamplingMatchesWithinOneMillionth) {
  CaseMaker maker;
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 4096; ++i) cases.push_back(maker.make());
  // Poles, the n.z = -0.0 sign choice, near-antipodal normals and the ends of [0, 1).
  const float below_one = std::nextafter(1.0f, 0.0f);
  const Vec3 normals[] = {{0, 0, 1}, {0, 0, -1}, {1, 0, -0.0}, {0, 1, 0},
                          normalize(Vec3{1e-4, -2e-4, -1}), normalize(Vec3{1e-4, 1e-4, 1})};
  const float numbers[] = {0.0f, 0.25f, 0.5f, 0.75f, below_one};
  for (const Vec3& n : normals)
    for (float u1 : numbers)
      for (float u2 : numbers) {
        ProbeCase c = maker.make();
        c.normal = f4(n);
        c.uv = {u1, u2, 0, 0};
        cases.push_back(c);
      }
  const auto results = run_probe(cases);
  for (size_t i = 0; i < cases.size(); ++i) {
    const ProbeCase& c = cases[i];
    const ProbeResult& g = results[i];
    const Vec3 n = vec(c.normal);
    SCOPED_TRACE("case " + std::to_string(i));
    const TangentFrame frame = orthonormal_basis(n);
    EXPECT_LE(max_abs(vec(g.tangent) - frame.tangent), 1e-6);
    EXPECT_LE(max_abs(vec(g.bitangent) - frame.bitangent), 1e-6);
    EXPECT_LE(max_abs(vec(g.cosine_sample) - sample_cosine_hemisphere(n, c.uv[0], c.uv[1])), 1e-6);
    const double lum = luminance(vec(c.colour));
    EXPECT_NEAR(g.scalars[3], lum, 1e-6 * lum);
  }
}

// Rays from |o| <= 10 at spheres of radius 0.1..3, clearly hitting (impact <= 0.9 r, so
// disc >= 0.19 r^2), clearly missing, or starting inside.
TEST(GlslReference, WellConditionedSphereHitsAgreeTo1e5Relative) {
  CaseMaker maker;
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 6000; ++i) {
    ProbeCase c = maker.make();
    const double r = c.sphere[3];
    const Vec3 center = vec(c.sphere);
    if (i % 3 == 2) {  // inside: only the exit root lies ahead
      c.origin = f4(center + maker.uniform(0, 0.9 * r) * maker.unit(), 0.0);
    } else {
      Vec3 origin = maker.box(10);
      while (length(origin - center) < 1.5 * r) origin = maker.box(10);
      const double impact = i % 3 == 0 ? maker.uniform(0, 0.9) : maker.uniform(1.1, 3);
      maker.aim(c, origin, center, r, impact * r);
    }
    cases.push_back(c);
  }
  const SphereStats stats = check_spheres(cases);
  EXPECT_EQ(stats.band_disagreements, 0);
  EXPECT_EQ(stats.hits, 4000);
  EXPECT_LE(stats.max_relative_error, 1e-5);
}

// A sphere of radius 0.5 at 1e3..1e4: the closest-approach discriminant keeps every hit a hit,
// t stays within the a-priori bound, and in practice within 8 ulps of the distance F.
TEST(GlslReference, FarSphereErrorStaysWithinAFewUlpsOfDistance) {
  CaseMaker maker;
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 4096; ++i) {
    ProbeCase c = maker.make();
    const Vec3 origin = maker.box(1);
    const Vec3 center = origin + std::pow(10.0, maker.uniform(3, 4)) * maker.unit();
    maker.aim(c, origin, center, 0.5, maker.uniform(0, 0.9 * 0.5));
    cases.push_back(c);
  }
  const SphereStats stats = check_spheres(cases);
  EXPECT_EQ(stats.band_disagreements, 0);
  EXPECT_EQ(stats.hits, 4096);
  EXPECT_LE(stats.max_relative_error, 1e-5);
  EXPECT_LE(stats.max_error_in_ulps_of_distance, 8);
}

// Impact parameters r (1 + eta) around tangency. The error band on the discriminant is below
// 1e-4 r^2 here (F <= 20 r), so for |eta| >= 1e-4 float must decide hit or miss correctly.
TEST(GlslReference, GrazingRaysDisagreeOnlyInsideTheDiscriminantBand) {
  CaseMaker maker;
  std::vector<ProbeCase> cases;
  std::vector<double> etas;
  for (int i = 0; i < 6000; ++i) {
    ProbeCase c = maker.make();
    const double r = c.sphere[3];
    const Vec3 center = vec(c.sphere);
    const Vec3 origin = center + maker.uniform(1.5, 20) * r * maker.unit();
    const double eta = i % 15 == 0 ? 0.0 : (i % 2 ? 1 : -1) * std::pow(10.0, -1 - (i % 7));
    maker.aim(c, origin, center, r, r * (1 + eta));
    cases.push_back(c);
    etas.push_back(eta);
  }
  const auto results = run_probe(cases);
  SphereStats stats;
  for (size_t i = 0; i < cases.size(); ++i) {
    const ProbeCase& c = cases[i];
    const double r = c.sphere[3];
    const float t = results[i].scalars[0];
    const auto roots = euclidean::sphere_roots(vec(c.origin), vec(c.direction), vec(c.sphere), r);
    ASSERT_LE(sphere_tolerance(c, roots).disc, 1e-4 * r * r) << "case " << i;
    EXPECT_TRUE(sphere_agrees(c, t, stats)) << "case " << i;
    if (std::abs(etas[i]) >= 1e-4) EXPECT_EQ(t != -1.0f, etas[i] < 0) << "case " << i;
  }
  EXPECT_GT(stats.hits, 2000);
}

// Secondary rays from points on the sphere with tMin > 0: outward rays never re-hit the
// surface they leave, inward rays find the far side.
TEST(GlslReference, RaysLeavingTheSurfaceNeverHitItAgain) {
  CaseMaker maker;
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 4096; ++i) {
    ProbeCase c = maker.make();
    const Vec3 n = maker.unit(), on_surface = vec(c.sphere) + c.sphere[3] * n;
    const Vec3 d = maker.unit();
    // tMin = the renderer's spawn offset (shaders/geometry/euclidean.glsl).
    c.origin = f4(on_surface, 1e-4 + max_abs(on_surface) / 32768.0);
    c.direction = f4(d, kFar);
    c.normal = f4(n);
    cases.push_back(c);
  }
  const auto results = run_probe(cases);
  SphereStats stats;
  for (size_t i = 0; i < cases.size(); ++i) {
    const ProbeCase& c = cases[i];
    const float t = results[i].scalars[0];
    EXPECT_TRUE(sphere_agrees(c, t, stats)) << "case " << i;
    if (dot(vec(c.direction), vec(c.normal)) > 1e-3) EXPECT_EQ(t, -1.0f) << "case " << i;
  }
  EXPECT_GT(stats.hits, 1800);
}

}  // namespace
}  // namespace geodesic::test
