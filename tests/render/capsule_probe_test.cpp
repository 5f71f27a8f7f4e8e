// The edge tubes' capsule routines in float GLSL (shaders/geometry/capsule.glsl, through the
// geometry probe) against their double twins (server/geometry/capsule.h): rays aimed through
// the body, past it, along the axis into a cap, from inside, and at random. A hit or miss must
// agree wherever the double answer does not change when the radius moves by 1e-3 (outside the
// grazing band); a hit's chart parameter within 1e-5 (|o| + s + 1) / cos, cos the incidence.
#include <cmath>
#include <cstdio>
#include <vector>

#include "geometry/capsule.h"
#include "geometry_probe.h"

namespace geodesic::test {
namespace {

struct CapsuleCase {
  Capsule capsule;
  Vec3 o, d;
  double s_max = 0;
};

CapsuleCase read_capsule_case(const ProbeCase& c) {
  return {{v3(c.capsule_a), v3(c.capsule_b), c.capsule_a[3]}, v3(c.chart), v3(c.normal),
          c.capsule_b[3]};
}

void store(ProbeCase& c, const Capsule& capsule, const Vec3& o, const Vec3& d) {
  c.capsule_a = f4(capsule.a, capsule.radius);
  c.capsule_b = f4(capsule.b, kFar);
  c.chart = f4(o, 0);
  c.normal = f4(d, 0);
}

double hit_or_inf(const CapsuleCase& c, double radius) {
  Capsule scaled = c.capsule;
  scaled.radius = radius;
  return intersect_capsule(scaled, c.o, c.d, 0, c.s_max);
}

TEST(CapsuleProbe, FloatIntersectionAndNormalMatchTheDoubleTwin) {
  const GeometryKind k = GeometryKind::Euclidean;  // the capsule lives in a chart: any model
  ProbeCaseMaker maker(k, 77);
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 8000; ++i) {
    ProbeCase c = maker.make();
    const Capsule capsule{sample.ball(0.8), sample.ball(0.8), sample.uniform(0.005, 0.2)};
    const Vec3 axis = capsule.b - capsule.a;
    const Vec3 on_axis = capsule.a + sample.uniform(-0.2, 1.2) * axis;
    const Vec3 side = normalize(cross(axis, sample.unit3()));
    switch (i % 5) {
      case 0:  // at the body or a cap, hitting
      case 1: {  // or missing by up to three radii
        const double f = i % 5 == 0 ? sample.uniform(0, 0.95) : sample.uniform(1.05, 3);
        const Vec3 o = sample.ball(1.5);
        store(c, capsule, o, normalize(on_axis + f * capsule.radius * side - o));
        break;
      }
      case 2: {  // along the axis, into a cap or past it
        const Vec3 n = normalize(axis) * (i % 2 ? 1.0 : -1.0);
        const Vec3 o = (i % 2 ? capsule.a : capsule.b) - 0.5 * n +
                       sample.uniform(0, 1.5) * capsule.radius * side;
        store(c, capsule, o, n);
        break;
      }
      case 3:  // from inside: the exit
        store(c, capsule, on_axis + sample.uniform(0, 0.9) * capsule.radius * side,
              sample.unit3());
        break;
      default:  // anywhere
        store(c, capsule, sample.ball(1.5), sample.unit3());
    }
    cases.push_back(c);
  }
  const auto results = run_probe(k, cases);
  int hits = 0, misses = 0, band = 0, caps = 0;
  double worst = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const CapsuleCase c = read_capsule_case(cases[i]);
    const double s = intersect_capsule(c.capsule, c.o, c.d, 0, c.s_max);
    const float g = results[i].capsule[0];
    const double r = c.capsule.radius;
    const bool stable = std::isinf(hit_or_inf(c, r * (1 - 1e-3))) ==
                            std::isinf(hit_or_inf(c, r * (1 + 1e-3))) &&
                        (std::isinf(s) || s > 1e-3);
    if (!stable) {
      ++band;
      continue;
    }
    if (std::isinf(s)) {
      ++misses;
      EXPECT_GE(g, 1e29f) << "case " << i << ": float hit at " << g;
      continue;
    }
    ++hits;
    const Vec3 x = c.o + s * c.d;
    const double cosine = std::abs(dot(normalize(c.d), capsule_normal(c.capsule, x)));
    const Vec3 axis = c.capsule.b - c.capsule.a;
    const double y = dot(x - c.capsule.a, axis) / dot(axis, axis);
    caps += y < 0 || y > 1;
    EXPECT_NEAR(distance_to_axis(c.capsule, x), r, 1e-12 * (1 + length(x))) << "case " << i;
    if (cosine < 0.05) continue;
    const double error = std::abs(g - s) * cosine / (length(c.o) + s + 1);
    worst = std::max(worst, error);
    EXPECT_LE(error, 1e-5) << "case " << i << ": float " << g << ", double " << s;
  }
  // The normal at the case's origin, away from the axis where its direction is undefined.
  int normals = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const CapsuleCase c = read_capsule_case(cases[i]);
    if (distance_to_axis(c.capsule, c.o) < 1e-3) continue;
    ++normals;
    const Vec3 n = capsule_normal(c.capsule, c.o);
    const Vec3 gn{results[i].capsule[1], results[i].capsule[2], results[i].capsule[3]};
    EXPECT_LE(length(gn - n), 1e-4) << "case " << i;
  }
  std::printf("capsule: %d hits (%d on a cap), %d misses, %d in the grazing band, %d normals; "
              "worst hit error %.2e (|o| + s + 1) / cos\n",
              hits, caps, misses, band, normals, worst);
  EXPECT_GT(hits, 2500);
  EXPECT_GT(misses, 2500);
  EXPECT_GT(caps, 300);
  EXPECT_LT(band, 400);
}

}  // namespace
}  // namespace geodesic::test
