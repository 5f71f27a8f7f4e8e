// The double-precision Euclidean reference: intersections at known parameters, the stable
// discriminant far away, Vulkan's barycentric convention, and the geodesic helpers.
#include "geometry/euclidean.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace geodesic::euclidean {
namespace {

constexpr double kInf = 1e300;

TEST(EuclideanSphere, HitsAtTheKnownDistance) {
  EXPECT_EQ(intersect_sphere({0, 0, -5}, {0, 0, 1}, {0, 0, 0}, 1, 0, kInf), 4.0);
  // Along a 3-4-5 diagonal towards a sphere of radius 2 at the origin.
  const auto t = intersect_sphere({3, 4, 0}, {-0.6, -0.8, 0}, {0, 0, 0}, 2, 0, kInf);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 3.0, 1e-15);
}

TEST(EuclideanSphere, TMinAndTMaxSelectTheRoot) {
  const Vec3 o{0, 0, -5}, d{0, 0, 1}, c{0, 0, 0};
  EXPECT_EQ(intersect_sphere(o, d, c, 1, 4.5, kInf), 6.0);  // past the entry: the exit
  EXPECT_FALSE(intersect_sphere(o, d, c, 1, 0, 3.5));      // both roots beyond tMax
  EXPECT_FALSE(intersect_sphere(o, d, c, 1, 6.5, kInf));   // both roots before tMin
  EXPECT_FALSE(intersect_sphere(o, d, c, 1, 4, 6));        // the interval is open
}

TEST(EuclideanSphere, InsideOriginReturnsTheExit) {
  EXPECT_EQ(intersect_sphere({0, 0, 0}, {1, 0, 0}, {0, 0, 0}, 2, 0, kInf), 2.0);
  EXPECT_EQ(intersect_sphere({0.5, 0, 0}, {1, 0, 0}, {0, 0, 0}, 2, 0, kInf), 1.5);
  EXPECT_EQ(intersect_sphere({0.5, 0, 0}, {-1, 0, 0}, {0, 0, 0}, 2, 0, kInf), 2.5);
}

TEST(EuclideanSphere, SphereBehindTheRayMisses) {
  EXPECT_FALSE(intersect_sphere({0, 0, 5}, {0, 0, 1}, {0, 0, 0}, 1, 0, kInf));
  EXPECT_FALSE(intersect_sphere({0, 3, -5}, {0, 0, 1}, {0, 0, 0}, 1, 0, kInf));  // passes by
}

TEST(EuclideanSphere, TangentRayTouchesOnceAndSlightlyOffMisses) {
  const SphereRoots roots = sphere_roots({-5, 1, 0}, {1, 0, 0}, {0, 0, 0}, 1);
  EXPECT_EQ(roots.disc, 0.0);
  EXPECT_EQ(roots.t0, 5.0);
  EXPECT_EQ(roots.t1, 5.0);
  EXPECT_EQ(intersect_sphere({-5, 1, 0}, {1, 0, 0}, {0, 0, 0}, 1, 0, kInf), 5.0);
  EXPECT_FALSE(intersect_sphere({-5, 1 + 1e-12, 0}, {1, 0, 0}, {0, 0, 0}, 1, 0, kInf));
  EXPECT_TRUE(intersect_sphere({-5, 1 - 1e-12, 0}, {1, 0, 0}, {0, 0, 0}, 1, 0, kInf));
}

// At distance 1e8, b^2 - c of the textbook formula loses every digit of the discriminant
// (ulp(1e16) = 2); the closest-approach form keeps the hit exact to round-off.
TEST(EuclideanSphere, FarSphereKeepsFullPrecision) {
  const double far = 1e8;
  const auto head_on = intersect_sphere({0, 0, 0}, {0, 0, 1}, {0, 0, far}, 1, 0, kInf);
  ASSERT_TRUE(head_on);
  EXPECT_NEAR(*head_on, far - 1, 1e-7);
  const auto offset = intersect_sphere({0.5, 0, 0}, {0, 0, 1}, {0, 0, far}, 1, 0, kInf);
  ASSERT_TRUE(offset);
  EXPECT_NEAR(*offset, far - std::sqrt(0.75), 1e-7);
}

TEST(EuclideanSphere, BothRootsLieOnTheSphere) {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> box(-10, 10);
  std::normal_distribution<double> g;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 o{box(gen), box(gen), box(gen)}, c{box(gen), box(gen), box(gen)};
    const Vec3 d = normalize(Vec3{g(gen), g(gen), g(gen)});
    const double r = 1 + std::abs(box(gen));
    const SphereRoots roots = sphere_roots(o, d, c, r);
    if (roots.disc < 0) {
      EXPECT_GT(length(o + dot(c - o, d) * d - c), r);  // the closest point is outside
      continue;
    }
    EXPECT_LE(roots.t0, roots.t1);
    for (double t : {roots.t0, roots.t1})
      EXPECT_NEAR(length(geodesic_point({o, d}, t) - c), r, 1e-12 * (r + length(o - c)));
  }
}

TEST(EuclideanTriangle, BarycentricsFollowVulkansConvention) {
  const Vec3 a{1, 0, 0}, b{0, 2, 0}, c{0, 0, 3};
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> g;
  for (int i = 0; i < 1000; ++i) {
    double u = unit(gen), v = unit(gen);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Vec3 p = (1 - u - v) * a + u * b + v * c;  // position = (1-u-v) a + u b + v c
    const Vec3 d = normalize(Vec3{g(gen), g(gen), g(gen)});
    if (std::abs(dot(d, cross(b - a, c - a))) < 1e-3) continue;  // nearly edge-on
    const auto hit = intersect_triangle({p - 3.0 * d, d}, a, b, c, 0, kInf);
    ASSERT_TRUE(hit) << i;
    EXPECT_NEAR(hit->t, 3.0, 1e-9);
    EXPECT_NEAR(hit->u, u, 1e-9);
    EXPECT_NEAR(hit->v, v, 1e-9);
  }
}

TEST(EuclideanTriangle, IsTwoSidedAndIncludesItsEdges) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  const auto front = intersect_triangle({{0.25, 0.25, 1}, {0, 0, -1}}, a, b, c, 0, kInf);
  const auto back = intersect_triangle({{0.25, 0.25, -1}, {0, 0, 1}}, a, b, c, 0, kInf);
  ASSERT_TRUE(front && back);
  EXPECT_EQ(front->t, 1.0);
  EXPECT_EQ(back->t, 1.0);
  const auto edge = intersect_triangle({{0.5, 0, 1}, {0, 0, -1}}, a, b, c, 0, kInf);
  ASSERT_TRUE(edge);
  EXPECT_EQ(edge->u, 0.5);
  EXPECT_EQ(edge->v, 0.0);
}

TEST(EuclideanTriangle, MissesOutsideParallelAndOutOfRange) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  EXPECT_FALSE(intersect_triangle({{0.6, 0.6, 1}, {0, 0, -1}}, a, b, c, 0, kInf));   // u+v > 1
  EXPECT_FALSE(intersect_triangle({{-0.1, 0.5, 1}, {0, 0, -1}}, a, b, c, 0, kInf));  // u < 0
  EXPECT_FALSE(intersect_triangle({{0.2, 0.2, 1}, {1, 0, 0}}, a, b, c, 0, kInf));    // parallel
  EXPECT_FALSE(intersect_triangle({{0.2, 0.2, 1}, {0, 0, -1}}, a, b, c, 0, 0.5));    // t > tMax
  EXPECT_FALSE(intersect_triangle({{0.2, 0.2, 1}, {0, 0, 1}}, a, b, c, 0, kInf));    // behind
}

TEST(EuclideanHelpers, ReflectionPreservesLengthAndMirrorsTheAngle) {
  std::mt19937_64 gen(3);
  std::normal_distribution<double> g;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 p{g(gen), g(gen), g(gen)}, d{g(gen), g(gen), g(gen)};
    const Vec3 n = normalize(Vec3{g(gen), g(gen), g(gen)});
    const Vec3 r = reflect_direction(p, d, n);
    EXPECT_NEAR(length(r), length(d), 1e-12 * length(d));
    EXPECT_NEAR(metric_dot(p, r, n), -metric_dot(p, d, n), 1e-12 * length(d));
    EXPECT_NEAR(length(cross(r - d, n)), 0.0, 1e-12 * length(d));  // only the normal part flips
    const Vec3 twice = reflect_direction(p, r, n);
    EXPECT_NEAR(length(twice - d), 0.0, 1e-12 * length(d));
  }
}

TEST(EuclideanHelpers, GeodesicFromAPointReachesItsTarget) {
  const Vec3 from{1, 2, 3}, to{4, -2, 3};
  EXPECT_EQ(geodesic_distance(from, to), 5.0);
  EXPECT_EQ(geodesic_distance(to, from), 5.0);
  const Vec3 d = geodesic_direction(from, to);
  EXPECT_NEAR(length(d), 1.0, 1e-15);
  EXPECT_NEAR(length(geodesic_point({from, d}, 5.0) - to), 0.0, 1e-14);
}

TEST(EuclideanHelpers, CameraRayAppliesThePose) {
  // A quarter turn about +y, then a translation: the camera's -z looks along -x.
  Mat4 pose = Mat4::identity();
  pose.m[0][0] = 0, pose.m[0][2] = 1, pose.m[2][0] = -1, pose.m[2][2] = 0;
  pose.m[0][3] = 1, pose.m[1][3] = 2, pose.m[2][3] = 3;
  const Ray ray = camera_ray(pose, {0, 0, -2});
  EXPECT_NEAR(length(ray.origin - Vec3{1, 2, 3}), 0.0, 1e-15);
  EXPECT_NEAR(length(ray.direction - Vec3{-1, 0, 0}), 0.0, 1e-15);
}

TEST(EuclideanHelpers, SurfaceOffsetGrowsWithTheCoordinates) {
  const Vec3 n{0, 0, 1};
  EXPECT_NEAR(offset_from_surface({0, 0, 0}, n).z, 1e-4, 1e-18);
  EXPECT_NEAR(offset_from_surface({-1e4, 0, 5}, n).z, 5 + 1e-4 + 1e4 / 32768.0, 1e-12);
  EXPECT_EQ(offset_from_surface({-1e4, 0, 5}, n).x, -1e4);
}

}  // namespace
}  // namespace geodesic::euclidean
