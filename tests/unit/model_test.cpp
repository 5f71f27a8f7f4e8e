// The double-precision model geometries (server/geometry/model.h): exponential map, isometries,
// geodesics, charts, reflections and parallel transport, each property checked in all three
// models at random. Sphere intersection is in model_sphere_test.cpp.
#include "geometry/model.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <numbers>

#include "model_sampler.h"
#include "test_constants.h"

namespace geodesic::test {
namespace {

using model::inner;
// Round-off bounds below are multiples of double's epsilon times the size of the coordinates
// involved, which grow like cosh(distance from the origin) in H3.

class ModelTest : public ::testing::TestWithParam<GeometryKind> {
 protected:
  GeometryKind k = GetParam();
  bool spherical = k == GeometryKind::Spherical;
  ModelSampler sample{k, 20240611};
  double reach = 3.0;  // how far from the origin random points lie (S3: short of pi)
};

TEST_P(ModelTest, ExpAndLogAtTheOriginAreInverse) {
  for (int i = 0; i < 1000; ++i) {
    const Vec3 w = sample.ball(reach);
    const Vec4 p = model::exp_origin(k, w);
    EXPECT_LE(point_error(k, p), 8 * kEps * max_abs(p) * max_abs(p));
    EXPECT_LE(max_abs(model::log_origin(k, p) - w), 1e-13) << i;
    EXPECT_NEAR(model::geodesic_distance(k, model::origin(), p), length(w), 1e-13) << i;
  }
  EXPECT_EQ(max_abs(model::exp_origin(k, {0, 0, 0}) - model::origin()), 0.0);
}

TEST_P(ModelTest, TranslationToCarriesTheOriginToQIsometrically) {
  for (int i = 0; i < 500; ++i) {
    const Vec3 w = sample.ball(reach);
    const Vec4 q = model::exp_origin(k, w);
    const Mat4 to = model::translation_to(k, q), from = model::translation_from(k, q);
    const double scale = max_abs(q) * max_abs(q);  // entries grow like cosh^2 in H3
    EXPECT_LE(max_abs(to * model::origin() - q), 1e-14 * scale) << i;
    EXPECT_LE(model::isometry_error(k, to), 1e-14 * scale) << i;
    EXPECT_LE(max_abs(from * q - model::origin()), 1e-14 * scale) << i;
    EXPECT_LE(max_abs(difference(to * from, Mat4::identity())), 1e-14 * scale) << i;
    EXPECT_LE(max_abs(difference(model::inverse_isometry(k, to), from)), 1e-15 * scale) << i;
    EXPECT_LE(max_abs(difference(model::translation(k, w), to)), 1e-14 * scale) << i;
    // Columns 0-2: the origin frame parallel-transported along the geodesic to q.
    const Vec4 u = model::geodesic_direction(k, model::origin(), q);
    const double d = model::geodesic_distance(k, model::origin(), q);
    const Vec4 axes[3] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    for (const Vec4& e : axes)
      EXPECT_LE(max_abs(to * e - model::parallel_transport(k, model::origin(), u, d, e)),
                1e-13 * scale) << i;
  }
}

TEST_P(ModelTest, IsometriesPreserveDistancesAndInvert) {
  for (int i = 0; i < 500; ++i) {
    const Mat4 g = sample.isometry(reach);
    const Vec4 a = sample.point(reach), b = sample.point(reach);
    const double scale = max_abs(g) * max_abs(g);
    EXPECT_LE(model::isometry_error(k, g), 1e-14 * scale) << i;
    EXPECT_NEAR(model::geodesic_distance(k, g * a, g * b), model::geodesic_distance(k, a, b),
                1e-12 * scale) << i;
    EXPECT_LE(max_abs(difference(model::inverse_isometry(k, g) * g, Mat4::identity())),
              1e-14 * scale) << i;
  }
}

TEST_P(ModelTest, GeodesicsStayOnTheModelAtTheRightDistance) {
  for (int i = 0; i < 1000; ++i) {
    const Vec4 p = sample.point(reach), v = sample.tangent(p);
    const double t = sample.uniform(spherical ? 0 : -3, 3);
    const Vec4 q = model::geodesic_point(k, p, v, t), u = model::geodesic_tangent(k, p, v, t);
    // The terms C(t) p and S(t) v may cancel: their size sets the round-off.
    const double terms = std::cosh(t) * (max_abs(p) + max_abs(v)), scale = terms * terms;
    EXPECT_LE(point_error(k, q), 8 * kEps * scale) << i;
    EXPECT_LE(tangent_error(k, q, u), 8 * kEps * scale) << i;
    EXPECT_NEAR(model::geodesic_distance(k, p, q), std::abs(t), 8 * kEps * scale) << i;
  }
}

TEST_P(ModelTest, GeodesicDirectionLeadsToTheTarget) {
  for (int i = 0; i < 1000; ++i) {
    const Vec4 from = sample.point(reach), to = sample.point(reach);
    const Vec4 v = model::geodesic_direction(k, from, to);
    const double d = model::geodesic_distance(k, from, to);
    const double scale = max_abs(from) * max_abs(to);
    EXPECT_LE(tangent_error(k, from, v), 1e-13 * scale) << i;
    EXPECT_LE(max_abs(model::geodesic_point(k, from, v, d) - to), 1e-12 * scale) << i;
    EXPECT_EQ(max_abs(model::sphere_normal(k, from, to) + model::geodesic_direction(k, to, from)),
              0.0) << i;
  }
  const Vec4 p = sample.point(reach);
  EXPECT_EQ(max_abs(model::geodesic_direction(k, p, p)), 0.0);  // undefined: the zero vector
}

TEST_P(ModelTest, ChartLinesAreStraight) {
  for (int i = 0; i < 1000; ++i) {
    // S3: short geodesics near the origin keep w > 0, inside the gnomonic chart.
    const Vec4 p = sample.point(spherical ? 0.5 : reach), v = sample.tangent(p);
    const double span = spherical ? 0.9 : 3;
    const double t[3] = {sample.uniform(-span, 0), sample.uniform(0, span), span};
    Vec3 x[3];
    for (int j = 0; j < 3; ++j) {
      x[j] = model::chart(k, model::geodesic_point(k, p, v, t[j]));
      const double s = model::chart_parameter(k, p, v, t[j]);
      const Vec3 on_line = model::chart(k, p) + s * model::chart_direction(k, p, v);
      EXPECT_LE(max_abs(x[j] - on_line), 1e-12 * (1 + max_abs(x[j]))) << i;
      EXPECT_NEAR(model::distance_from_chart_parameter(k, p, v, s), t[j], 1e-11) << i;
    }
    const Vec3 a = x[1] - x[0], b = x[2] - x[0];
    EXPECT_LE(length(cross(a, b)), 1e-12 * length(a) * length(b)) << i;
  }
}

TEST_P(ModelTest, LiftInvertsTheChart) {
  for (int i = 0; i < 1000; ++i) {
    const Vec4 q = sample.point(spherical ? 1.5 : reach);  // S3: inside the chart, w > 0
    // 1 - |x|^2 = 1 / w^2 loses digits towards the Klein sphere: lift's error grows like w^3.
    EXPECT_LE(max_abs(model::lift(k, model::chart(k, q)) - q), 8 * kEps * (1 + std::pow(q.w, 3)))
        << i;
  }
}

// atan2 keeps the inverse right past a quarter turn, while the geodesic is still in w > 0.
TEST(SphericalModel, ChartParameterGoesPastAQuarterTurn) {
  const GeometryKind k = GeometryKind::Spherical;
  const Vec4 p = model::exp_origin(k, {-1, 0, 0}), v{std::cos(1.0), 0, 0, std::sin(1.0)};
  ASSERT_LE(tangent_error(k, p, v), 1e-15);
  for (double t : {1.0, kPi / 2, 2.0, 2.5}) {
    ASSERT_GT(model::geodesic_point(k, p, v, t).w, 0);
    const double s = model::chart_parameter(k, p, v, t);
    EXPECT_NEAR(model::distance_from_chart_parameter(k, p, v, s), t, 1e-13);
    // The antipodal geodesic has the same chart line, in the w < 0 hemisphere.
    EXPECT_NEAR(model::distance_from_chart_parameter(k, -p, -v, s), t, 1e-13);
  }
}

TEST_P(ModelTest, ReflectionInAChartPlaneIsAnInvolutiveIsometryFixingThePlane) {
  for (int i = 0; i < 500; ++i) {
    const Vec3 n = sample.unit3();
    const double delta = sample.uniform(-0.9, 0.9) * (k == GeometryKind::Hyperbolic ? 1 : 3);
    const Mat4 r = model::reflection_in_chart_plane(k, n, delta);
    EXPECT_LE(model::isometry_error(k, r), 1e-13) << i;
    EXPECT_LE(max_abs(difference(r * r, Mat4::identity())), 1e-13) << i;
    // A point of the plane (inside the Klein ball in H3) and the plane's normal there.
    const double room = k == GeometryKind::Hyperbolic ? std::sqrt(1 - delta * delta) : 3;
    const Vec3 x = delta * n + sample.uniform(0, 0.9) * room * normalize(cross(n, sample.unit3()));
    const Vec4 q = model::lift(k, x), normal = model::chart_plane_normal(k, q, n, delta);
    EXPECT_LE(max_abs(r * q - q), 1e-13) << i;
    EXPECT_LE(tangent_error(k, q, normal), 1e-13) << i;
    EXPECT_LE(max_abs(r * normal + normal), 1e-13) << i;
    EXPECT_GT(dot(model::chart_direction(k, q, normal), n), 0) << i;  // towards +N
  }
}

TEST_P(ModelTest, ParallelTransportPreservesTheForm) {
  for (int i = 0; i < 500; ++i) {
    const Vec4 p = sample.point(reach), v = sample.tangent(p);
    const Vec4 a = sample.tangent(p), b = sample.tangent(p);
    const double t = sample.uniform(-3, 3);
    const Vec4 q = model::geodesic_point(k, p, v, t);
    const Vec4 ta = model::parallel_transport(k, p, v, t, a);
    const Vec4 tb = model::parallel_transport(k, p, v, t, b);
    const double terms = std::cosh(t) * (max_abs(p) + max_abs(v)), scale = terms * terms;
    EXPECT_NEAR(inner(k, ta, tb), inner(k, a, b), 8 * kEps * scale) << i;
    EXPECT_LE(tangent_error(k, q, ta), 8 * kEps * scale) << i;
    EXPECT_LE(max_abs(model::parallel_transport(k, p, v, t, v) -
                      model::geodesic_tangent(k, p, v, t)), 8 * kEps * scale) << i;
  }
}

TEST_P(ModelTest, ReorthonormalizeRepairsAPerturbedIsometry) {
  for (int i = 0; i < 200; ++i) {
    Mat4 g = sample.isometry(reach);
    const Mat4 exact = g;
    for (auto& row : g.m)
      for (double& x : row) x *= 1 + sample.uniform(-1e-6, 1e-6);
    if (k == GeometryKind::Euclidean) g.m[3] = {0, 0, 0, 1};  // affine bottom row
    const Mat4 r = model::reorthonormalize(k, g);
    EXPECT_LE(model::isometry_error(k, r), 1e-13 * max_abs(r) * max_abs(r)) << i;
    // A relative 1e-6 on entries of size cosh moves an H3 frame by up to about 1e-6 cosh^2.
    EXPECT_LE(max_abs(difference(r, exact)), 1e-5 * max_abs(exact) * max_abs(exact)) << i;
  }
}

TEST_P(ModelTest, OffsetFromSurfaceStepsAlongTheNormal) {
  for (int i = 0; i < 200; ++i) {
    const Vec4 q = sample.point(reach), n = sample.tangent(q);
    const Vec4 spawn = model::offset_from_surface(k, q, n);
    const double h = model::surface_offset_length(k, q);
    EXPECT_LE(point_error(k, spawn), 1e-15 * max_abs(q) * max_abs(q));
    EXPECT_NEAR(model::geodesic_distance(k, q, spawn), h, 1e-9 * h) << i;
    EXPECT_GE(h, 1e-4 + 0x1p-15 * max_abs(q.xyz()));
  }
  // E3: the shader's 1e-4 plus 2^-15 of the largest |x|, |y|, |z|.
  const Vec4 up{0, 0, 1, 0};
  const GeometryKind e = GeometryKind::Euclidean;
  EXPECT_NEAR(model::offset_from_surface(e, model::origin(), up).z, 1e-4, 1e-18);
  EXPECT_NEAR(model::offset_from_surface(e, {-1e4, 0, 5, 1}, up).z, 5 + 1e-4 + 1e4 / 32768.0,
              1e-12);
}

// The antipode of S3: every geodesic from p reaches -p at pi, so no direction is preferred.
TEST(SphericalModel, AntipodeIsReachedFromEveryDirection) {
  const GeometryKind k = GeometryKind::Spherical;
  ModelSampler sample(k, 5);
  for (int i = 0; i < 200; ++i) {
    const Vec4 p = sample.point(3), v = sample.tangent(p);
    EXPECT_LE(max_abs(model::geodesic_point(k, p, v, kPi) + p), 1e-15) << i;
    EXPECT_EQ(max_abs(model::geodesic_direction(k, p, -p)), 0.0) << i;
    EXPECT_NEAR(model::geodesic_distance(k, p, -p), kPi, 1e-15) << i;
    // Just short of the antipode the direction is still defined.
    const Vec4 near = model::geodesic_point(k, p, v, kPi - 1e-6);
    EXPECT_LE(max_abs(model::geodesic_direction(k, p, near) - v), 1e-9) << i;
  }
  const Vec4 antipode{0, 0, 0, -1};
  const Mat4 half_turn = model::translation_to(k, antipode);
  EXPECT_EQ(max_abs(half_turn * model::origin() - antipode), 0.0);
  EXPECT_EQ(model::isometry_error(k, half_turn), 0.0);
  const Mat4 back = model::translation_from(k, antipode) * half_turn;
  EXPECT_EQ(max_abs(difference(back, Mat4::identity())), 0.0);
  EXPECT_EQ(max_abs(model::log_origin(k, antipode)), 0.0);  // documented: not invertible there
  // Near it, the (1 - w) form keeps translation_to an isometry.
  const Vec4 q = model::exp_origin(k, {kPi - 1e-9, 0, 0});
  EXPECT_LE(model::isometry_error(k, model::translation_to(k, q)), 1e-15);
  EXPECT_LE(max_abs(model::translation_to(k, q) * model::origin() - q), 1e-15);
}

// The E3 cases of the former euclidean_test: the pose of a camera moves its ray.
TEST(EuclideanModel, CameraPoseMovesTheRay) {
  // A quarter turn about +y, then a translation: the camera's -z looks along -x.
  const GeometryKind e = GeometryKind::Euclidean;
  const Mat4 pose = model::translation(e, {1, 2, 3}) * model::rotation({0, 1, 0}, kPi / 2);
  const Vec4 p = pose * model::origin();
  const Vec4 v = model::normalize_tangent(e, p, pose * Vec4{0, 0, -2, 0});
  EXPECT_LE(max_abs(p - Vec4{1, 2, 3, 1}), 1e-15);
  EXPECT_LE(max_abs(v - Vec4{-1, 0, 0, 0}), 1e-15);
  EXPECT_EQ(model::geodesic_distance(e, {1, 2, 3, 1}, {4, -2, 3, 1}), 5.0);
}

INSTANTIATE_TEST_SUITE_P(AllGeometries, ModelTest,
                         ::testing::Values(GeometryKind::Euclidean, GeometryKind::Hyperbolic,
                                           GeometryKind::Spherical),
                         geometry_label);

}  // namespace
}  // namespace geodesic::test
