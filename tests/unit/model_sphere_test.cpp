// Geodesic spheres and chart triangles in the double-precision models: known distances, the
// choice of root in (t_min, t_max), brute-force root finding, the closed-form angular radius,
// and (E3) the far-sphere and barycentric cases of the former euclidean_test.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <numbers>
#include <optional>

#include "geometry/model.h"
#include "model_sampler.h"
#include "test_constants.h"

namespace geodesic::test {
namespace {

constexpr double kInf = 1e300;

class ModelSphereTest : public ::testing::TestWithParam<GeometryKind> {
 protected:
  GeometryKind k = GetParam();
  bool spherical = k == GeometryKind::Spherical;
  ModelSampler sample{k, 7};

  // The first t in (t_min, t_max) where the distance to c crosses r: a 2e-3 grid, then bisection.
  std::optional<double> brute_force(const Vec4& p, const Vec4& v, const Vec4& c, double r,
                                    double t_min, double t_max) const {
    const auto f = [&](double t) {
      return model::geodesic_distance(k, model::geodesic_point(k, p, v, t), c) - r;
    };
    const double h = 2e-3;
    for (double a = t_min; a < t_max; a += h) {
      double lo = a, hi = std::min(a + h, t_max);
      if ((f(lo) > 0) == (f(hi) > 0)) continue;
      for (int i = 0; i < 100; ++i) {
        const double mid = (lo + hi) / 2;
        ((f(lo) > 0) == (f(mid) > 0) ? lo : hi) = mid;
      }
      return lo;
    }
    return std::nullopt;
  }
};

// A sphere of radius r centred at distance d along the ray: roots d - r and d + r.
TEST_P(ModelSphereTest, HitsAtTheKnownDistances) {
  const Vec4 p = model::origin(), v{0, 0, 1, 0};
  const double d = spherical ? 2 : 5, r = spherical ? 0.5 : 1;
  const Vec4 c = model::geodesic_point(k, p, v, d);
  const auto roots = model::sphere_roots(k, p, v, c, r);
  EXPECT_NEAR(roots.t0, d - r, 1e-14);
  EXPECT_NEAR(roots.t1, d + r, 1e-14);
  EXPECT_NEAR(model::intersect_sphere(k, p, v, c, r, 0, kInf).value(), d - r, 1e-14);
  EXPECT_NEAR(model::intersect_sphere(k, p, v, c, r, d, kInf).value(), d + r, 1e-14);  // exit
  EXPECT_FALSE(model::intersect_sphere(k, p, v, c, r, 0, d - r - 0.5));  // both beyond t_max
  EXPECT_FALSE(model::intersect_sphere(k, p, v, c, r, d - r, d + r));    // the interval is open
  // From the centre, the exit lies at r in every direction (-<c,c> = 1 to eps |c|^2).
  EXPECT_NEAR(model::intersect_sphere(k, c, sample.tangent(c), c, r, 0, kInf).value(), r,
              8 * DBL_EPSILON * max_abs(c) * max_abs(c));
  // Behind the ray: E3 and H3 miss; S3 comes round to it at 2 pi - d - r.
  const Vec4 behind = model::geodesic_point(k, p, v, -d);
  const auto back = model::intersect_sphere(k, p, v, behind, r, 0, kInf);
  if (spherical)
    EXPECT_NEAR(back.value(), 2 * kPi - d - r, 1e-14);
  else
    EXPECT_FALSE(back);
}

TEST_P(ModelSphereTest, FirstHitMatchesBruteForceRootFinding) {
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec4 p = sample.point(2), c = sample.point(2);
    const double r = sample.uniform(0.05, spherical ? 3 : 2);
    // Half the rays aimed roughly at the centre, so that about half of them hit.
    Vec4 v = sample.tangent(p);
    if (i % 2) v = model::normalize_tangent(k, p, model::geodesic_direction(k, p, c) + 0.6 * v);
    const double t_min = sample.uniform(0, 1), t_max = spherical ? 4 * kPi : 8;
    const auto roots = model::sphere_roots(k, p, v, c, r);
    if (std::abs(roots.disc) < 1e-2) continue;  // grazing: the grid could step over the dip
    const auto exact = model::intersect_sphere(k, p, v, c, r, t_min, t_max);
    const auto brute = brute_force(p, v, c, r, t_min, t_max);
    ASSERT_EQ(exact.has_value(), brute.has_value()) << i << " disc " << roots.disc;
    if (!exact) continue;
    ++hits;
    EXPECT_NEAR(*exact, *brute, 1e-10) << i;
    for (double t : {roots.t0, roots.t1})  // both roots lie on the sphere
      EXPECT_NEAR(model::geodesic_distance(k, model::geodesic_point(k, p, v, t), c), r, 1e-12) << i;
  }
  EXPECT_GT(hits, 100);
}

// Seen from distance d, a sphere of radius r has angular radius alpha with sin alpha = r / d
// (E3), sinh r / sinh d (H3), sin r / sin d (S3): the ray at alpha grazes it, where the
// right triangle (centre, viewer, tangent point) puts the tangent point.
TEST_P(ModelSphereTest, RayAtTheAngularRadiusGrazes) {
  for (int i = 0; i < 500; ++i) {
    const Vec4 p = sample.point(2), e = sample.tangent(p), f = sample.perpendicular(p, e);
    const double r = sample.uniform(0.05, spherical ? 1.4 : 2);
    const double d = sample.uniform(r + 0.1, spherical ? kPi - r - 0.1 : r + 5);
    const Vec4 c = model::geodesic_point(k, p, e, d);
    double sin_alpha = r / d, t_tangent = std::sqrt(d * d - r * r);
    if (k == GeometryKind::Hyperbolic)
      sin_alpha = std::sinh(r) / std::sinh(d), t_tangent = std::acosh(std::cosh(d) / std::cosh(r));
    if (spherical)
      sin_alpha = std::sin(r) / std::sin(d), t_tangent = std::acos(std::cos(d) / std::cos(r));
    const auto ray = [&](double alpha) { return std::cos(alpha) * e + std::sin(alpha) * f; };
    const double alpha = std::asin(sin_alpha);
    const auto roots = model::sphere_roots(k, p, ray(alpha), c, r);
    const double scale = max_abs(p) * max_abs(c);
    EXPECT_NEAR(roots.disc, 0, 1e-13 * scale) << i;
    // Just inside, the two roots straddle the tangent point; just outside, a miss.
    const auto inside = model::sphere_roots(k, p, ray(alpha * (1 - 1e-8)), c, r);
    EXPECT_GT(inside.disc, 0) << i;
    EXPECT_NEAR((inside.t0 + inside.t1) / 2, t_tangent, 1e-7) << i;
    EXPECT_LT(model::sphere_roots(k, p, ray(alpha * (1 + 1e-8)), c, r).disc, 0) << i;
  }
}

INSTANTIATE_TEST_SUITE_P(AllGeometries, ModelSphereTest,
                         ::testing::Values(GeometryKind::Euclidean, GeometryKind::Hyperbolic,
                                           GeometryKind::Spherical),
                         geometry_label);

constexpr GeometryKind kE = GeometryKind::Euclidean;
std::optional<double> hit_e3(const Vec3& o, const Vec3& d, const Vec3& c, double r, double t_min,
                             double t_max) {
  return model::intersect_sphere(kE, {o, 1}, {d, 0}, {c, 1}, r, t_min, t_max);
}

TEST(EuclideanSphere, HitsAlongADiagonalAndFromInside) {
  EXPECT_EQ(hit_e3({0, 0, -5}, {0, 0, 1}, {0, 0, 0}, 1, 0, kInf), 4.0);
  EXPECT_NEAR(hit_e3({3, 4, 0}, {-0.6, -0.8, 0}, {0, 0, 0}, 2, 0, kInf).value(), 3.0, 1e-15);
  EXPECT_EQ(hit_e3({0.5, 0, 0}, {1, 0, 0}, {0, 0, 0}, 2, 0, kInf), 1.5);
  EXPECT_EQ(hit_e3({0.5, 0, 0}, {-1, 0, 0}, {0, 0, 0}, 2, 0, kInf), 2.5);
  EXPECT_FALSE(hit_e3({0, 3, -5}, {0, 0, 1}, {0, 0, 0}, 1, 0, kInf));  // passes by
}

TEST(EuclideanSphere, TangentRayTouchesOnceAndSlightlyOffMisses) {
  const auto roots = model::sphere_roots(kE, {-5, 1, 0, 1}, {1, 0, 0, 0}, model::origin(), 1);
  EXPECT_EQ(roots.disc, 0.0);
  EXPECT_EQ(roots.t0, 5.0);
  EXPECT_EQ(roots.t1, 5.0);
  EXPECT_FALSE(hit_e3({-5, 1 + 1e-12, 0}, {1, 0, 0}, {0, 0, 0}, 1, 0, kInf));
  EXPECT_TRUE(hit_e3({-5, 1 - 1e-12, 0}, {1, 0, 0}, {0, 0, 0}, 1, 0, kInf));
}

// At distance 1e8, b^2 - c of the textbook formula loses every digit of the discriminant
// (ulp(1e16) = 2); the closest-approach form keeps the hit exact to round-off.
TEST(EuclideanSphere, FarSphereKeepsFullPrecision) {
  const double far = 1e8;
  EXPECT_NEAR(hit_e3({0, 0, 0}, {0, 0, 1}, {0, 0, far}, 1, 0, kInf).value(), far - 1, 1e-7);
  EXPECT_NEAR(hit_e3({0.5, 0, 0}, {0, 0, 1}, {0, 0, far}, 1, 0, kInf).value(),
              far - std::sqrt(0.75), 1e-7);
}

using model::intersect_chart_triangle;

TEST(ChartTriangle, BarycentricsFollowVulkansConvention) {
  const Vec3 a{1, 0, 0}, b{0, 2, 0}, c{0, 0, 3};
  ModelSampler sample(kE, 11);
  for (int i = 0; i < 1000; ++i) {
    double u = sample.uniform(0, 1), v = sample.uniform(0, 1);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Vec3 p = (1 - u - v) * a + u * b + v * c;  // position = (1-u-v) a + u b + v c
    const Vec3 d = sample.unit3();
    if (std::abs(dot(d, cross(b - a, c - a))) < 1e-3) continue;  // nearly edge-on
    const auto hit = intersect_chart_triangle(p - 3.0 * d, d, a, b, c, 0, kInf);
    ASSERT_TRUE(hit) << i;
    EXPECT_NEAR(hit->s, 3.0, 1e-9);
    EXPECT_NEAR(hit->u, u, 1e-9);
    EXPECT_NEAR(hit->v, v, 1e-9);
  }
}

TEST(ChartTriangle, IsTwoSidedAndIncludesItsEdges) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  const auto front = intersect_chart_triangle({0.25, 0.25, 1}, {0, 0, -1}, a, b, c, 0, kInf);
  const auto back = intersect_chart_triangle({0.25, 0.25, -1}, {0, 0, 1}, a, b, c, 0, kInf);
  ASSERT_TRUE(front && back);
  EXPECT_EQ(front->s, 1.0);
  EXPECT_EQ(back->s, 1.0);
  const auto edge = intersect_chart_triangle({0.5, 0, 1}, {0, 0, -1}, a, b, c, 0, kInf);
  ASSERT_TRUE(edge);
  EXPECT_EQ(edge->u, 0.5);
  EXPECT_EQ(edge->v, 0.0);
}

TEST(ChartTriangle, MissesOutsideParallelAndOutOfRange) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  EXPECT_FALSE(intersect_chart_triangle({0.6, 0.6, 1}, {0, 0, -1}, a, b, c, 0, kInf));   // u+v > 1
  EXPECT_FALSE(intersect_chart_triangle({-0.1, 0.5, 1}, {0, 0, -1}, a, b, c, 0, kInf));  // u < 0
  EXPECT_FALSE(intersect_chart_triangle({0.2, 0.2, 1}, {1, 0, 0}, a, b, c, 0, kInf));    // parallel
  EXPECT_FALSE(intersect_chart_triangle({0.2, 0.2, 1}, {0, 0, -1}, a, b, c, 0, 0.5));    // s > sMax
  EXPECT_FALSE(intersect_chart_triangle({0.2, 0.2, 1}, {0, 0, 1}, a, b, c, 0, kInf));    // behind
}

}  // namespace
}  // namespace geodesic::test
