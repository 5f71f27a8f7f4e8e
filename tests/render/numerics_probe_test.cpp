// Numerics suite, device part: float GLSL against the double twins in the stiff and extreme
// cases: H3 objects 15-20 away, spheres of radius 1e-4, H3 spheres of radius 20, S3 spheres
// of radius about pi/2, and a light at the antipode in S3. Each case prints a row of the
// table in docs/numerics.md; the assertions hold each sphere hit to geometry_probe.h's
// tolerance (16 u (S + |t|) + 1e-6) and state what float achieves there.
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "geometry_probe.h"

namespace geodesic::test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr GeometryKind kE = GeometryKind::Euclidean, kH = GeometryKind::Hyperbolic,
                       kS = GeometryKind::Spherical;

// The probe case of a ray from p towards the sphere (c, r), tilted from the direction to c
// by `fraction` of the sphere's angular radius seen from p (which is <= 1: it hits).
ProbeCase aimed_within(GeometryKind k, ProbeCaseMaker& maker, const Vec4& p, const Vec4& c,
                       double r, double fraction) {
  ModelSampler& sample = maker.sample();
  const double d = model::geodesic_distance(k, p, c);
  double sin_alpha = r / d;  // the angular radius, sin alpha = r/d, sinh r/sinh d, sin r/sin d
  if (k == kH) sin_alpha = std::sinh(r) / std::sinh(d);
  if (k == kS) sin_alpha = std::sin(r) / std::sin(d);
  const double angle = fraction * std::asin(std::min(1.0, sin_alpha));
  const Vec4 e = model::geodesic_direction(k, p, c), f = sample.perpendicular(p, e);
  ProbeCase out = maker.make();
  out.point = f4(p);
  out.tangent = f4(maker.rounded(std::cos(angle) * e + std::sin(angle) * f));
  out.sphere = f4(c);
  out.params = {0, float(r), 0, kFar};
  return out;
}

// Runs the cases, checks every hit, prints a table row and returns the statistics.
SphereStats sphere_row(const char* name, GeometryKind k, const std::vector<ProbeCase>& cases) {
  const auto results = run_probe(k, cases);
  SphereStats stats;
  for (size_t i = 0; i < cases.size(); ++i)
    EXPECT_TRUE(sphere_agrees(k, cases[i], results[i].scalars[0], stats, 16, 1e-6))
        << name << " case " << i;
  std::printf("| %-42s | %-10s | %5zu | %5d | %4d | %9.2e | %9.2e | %8.3g |\n", name,
              geometry_name(k), cases.size(), stats.hits, stats.band, stats.worst_error,
              stats.worst_relative, stats.worst_ulps);
  return stats;
}

void print_header() {
  std::printf("| %-42s | %-10s | %5s | %5s | %4s | %9s | %9s | %8s |\n", "sphere case", "geometry",
              "rays", "hits", "band", "max|dt|", "max|dt|/t", "u(S+|t|)");
}

// Rays from the origin at H3 spheres 15-20 away that look 0.007-0.4 rad wide (radius d - 5 ..
// d - 1), and at radius-1 spheres there, which look 7e-7 rad wide: a dozen float ulps of a
// direction, so only head-on rays hit.
TEST(FloatNumerics, FarHyperbolicSpheresSeenFromTheOrigin) {
  ProbeCaseMaker maker(kH, 1);
  ModelSampler& sample = maker.sample();
  print_header();
  for (bool unit_radius : {false, true}) {
    std::vector<ProbeCase> cases;
    for (int i = 0; i < 4096; ++i) {
      const double d = sample.uniform(15, 20), r = unit_radius ? 1 : d - sample.uniform(1, 5);
      const Vec4 c = maker.rounded(model::exp_origin(kH, d * sample.unit3()));
      cases.push_back(aimed_within(kH, maker, model::origin(), c, r, sample.uniform(0, 0.9)));
    }
    const SphereStats stats = sphere_row(unit_radius ? "H3 r = 1 at d = 15..20, from the origin"
                                                     : "H3 r = d-5..d-1 at d = 15..20, from origin",
                                         kH, cases);
    if (!unit_radius) {
      EXPECT_LE(stats.worst_relative, 1e-6);  // float achieves about 1e-7 relative here
      EXPECT_GT(stats.hits, 4000);
    }
  }
}

// The camera itself 15 from the origin: coordinates ~1.6e6 round to ~0.1, and so do the hits
// on a sphere 3 away. Why the renderer must keep the camera (or the cell) near the origin.
TEST(FloatNumerics, CameraFarFromTheOriginInH3) {
  ProbeCaseMaker maker(kH, 2);
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 4096; ++i) {
    const Vec4 p = maker.rounded(model::exp_origin(kH, 15 * sample.unit3()));
    const Vec4 c = maker.rounded(model::geodesic_point(kH, p, sample.tangent(p), 3));
    cases.push_back(aimed_within(kH, maker, p, c, 1, sample.uniform(0, 0.9)));
  }
  const SphereStats stats = sphere_row("H3 r = 1 at d = 3, camera 15 from origin", kH, cases);
  EXPECT_GT(stats.worst_error, 1e-3);  // documented: coordinates ~1.6e6 leave t uncertain
}

// Radius 1e-4 at distance 0.5-3 (E3: up to 10) from a ray origin near the model origin.
TEST(FloatNumerics, TinySpheres) {
  for (GeometryKind k : {kE, kH, kS}) {
    ProbeCaseMaker maker(k, 3);
    ModelSampler& sample = maker.sample();
    std::vector<ProbeCase> cases;
    for (int i = 0; i < 4096; ++i) {
      const Vec4 p = maker.rounded(sample.point(1));
      const double d = sample.uniform(0.5, k == kE ? 10 : 3);
      const Vec4 c = maker.rounded(model::geodesic_point(k, p, sample.tangent(p), d));
      cases.push_back(aimed_within(k, maker, p, c, 1e-4, sample.uniform(0, 0.9)));
    }
    const SphereStats stats = sphere_row("radius 1e-4 at d = 0.5..3 (E3 ..10)", k, cases);
    EXPECT_GT(stats.hits, 3900);
    EXPECT_LE(stats.worst_relative, 1e-5);
  }
}

// H3 radius 20 (coordinates of its points ~2.4e8): from inside, exits near t = 20 - d; from
// outside at 21-25, entries at d - 20. S3 radius pi/2 - 1e-3, pi/2, pi/2 + 1e-3 and 3 (the
// sphere around c is the small sphere of radius pi - r around -c).
TEST(FloatNumerics, HugeSpheres) {
  ProbeCaseMaker hmaker(kH, 4);
  ModelSampler& h = hmaker.sample();
  for (bool inside : {true, false}) {
    std::vector<ProbeCase> cases;
    for (int i = 0; i < 4096; ++i) {
      const double d = inside ? h.uniform(0, 5) : h.uniform(21, 25);
      const Vec4 c = hmaker.rounded(model::exp_origin(kH, d * h.unit3()));
      ProbeCase pc = inside ? hmaker.make() : aimed_within(kH, hmaker, model::origin(), c, 20, h.uniform(0, 0.9));
      if (inside) pc.point = f4(model::origin()), pc.sphere = f4(c), pc.params = {0, 20, 0, kFar};
      cases.push_back(pc);
    }
    const SphereStats stats = sphere_row(inside ? "H3 r = 20, camera inside (d = 0..5)"
                                                : "H3 r = 20, camera outside (d = 21..25)",
                                         kH, cases);
    EXPECT_GT(stats.hits, 4000);
    EXPECT_LE(stats.worst_relative, 1e-5);
  }
  ProbeCaseMaker smaker(kS, 5);
  for (double r : {kPi / 2 - 1e-3, kPi / 2, kPi / 2 + 1e-3, 3.0}) {
    std::vector<ProbeCase> cases;
    for (int i = 0; i < 4096; ++i) {
      ProbeCase pc = smaker.make();  // random ray and centre anywhere in S3
      pc.params = {0, float(r), 0, kFar};
      cases.push_back(pc);
    }
    const std::string name = "S3 r = " + std::to_string(r) + ", random rays";
    const SphereStats stats = sphere_row(name.c_str(), kS, cases);
    EXPECT_GT(stats.hits, 1000);
  }
}

// A light at the antipode of a shading point in S3: every direction leads to it, so
// geodesicDirection is the zero vector (no NaN), the distance is pi, and a sphere around it
// is hit at pi - r in every direction. Just short of the antipode the direction is defined.
TEST(FloatNumerics, LightAtTheSphericalAntipode) {
  ProbeCaseMaker maker(kS, 6);
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 4096; ++i) {
    ProbeCase c = maker.make();
    const Vec4 p = v4(c.point), v = v4(c.tangent);
    const bool exact = i % 2 == 0;
    c.target = f4(exact ? -p : model::geodesic_point(kS, p, v, kPi - 1e-3));
    c.sphere = f4(-p);
    c.params = {0, float(sample.uniform(0.01, 1)), 0, kFar};
    cases.push_back(c);
  }
  const auto results = run_probe(kS, cases);
  double worst_distance = 0, worst_near_direction = 0, worst_hit = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const ProbeResult& g = results[i];
    const Vec4 v = v4(cases[i].tangent);
    for (float x : g.towards) ASSERT_TRUE(std::isfinite(x)) << i;
    for (float x : g.sphere_normal) ASSERT_TRUE(std::isfinite(x)) << i;
    const double r = cases[i].params[1];
    worst_hit = std::max(worst_hit, std::abs(g.scalars[0] - (kPi - r)));
    if (i % 2 == 0) {
      EXPECT_EQ(max_abs(v4(g.towards)), 0.0) << i;
      worst_distance = std::max(worst_distance, std::abs(g.scalars[1] - kPi));
    } else {
      worst_near_direction = std::max(worst_near_direction, max_abs(v4(g.towards) - v));
    }
  }
  std::printf("S3 antipode: direction exactly 0 (no NaN) at the antipode; |distance - pi| <= %.2g;"
              " 1e-3 short of it, direction within %.2g; sphere around it hit at pi - r within %.2g\n",
              worst_distance, worst_near_direction, worst_hit);
  EXPECT_LE(worst_distance, 1e-6);
  EXPECT_LE(worst_near_direction, 1e-3);  // conditioning 1 / sin(1e-3): float gives ~1e-4
  EXPECT_LE(worst_hit, 1e-5);
}

}  // namespace
}  // namespace geodesic::test
