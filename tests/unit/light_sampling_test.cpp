// The physical model's sampling routines against the densities they state (chi-square), the
// BSDF's energy conservation and reciprocity, and the curved-space light geometry: cones that
// graze geodesic spheres, triangle areas and their Jacobian, and a point light's falloff.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "chi_square.h"
#include "geometry/model.h"
#include "geometry/sampling.h"
#include "twins/bsdf.h"
#include "render/prepare/emitters.h"
#include "scene/shape.h"
#include "common/shape_kinds.h"
#include "test_constants.h"

namespace geodesic {
namespace {

using test::kPi;
constexpr double kSignificance = 1e-3;
const GeometryKind kKinds[] = {GeometryKind::Euclidean, GeometryKind::Hyperbolic,
                               GeometryKind::Spherical};

TEST(LightSampling, PhongLobeFollowsItsDensity) {
  const Vec3 axis = normalize(Vec3{0.2, -0.4, 0.9});
  for (double exponent : {0.0, 1.0, 10.0, 50.0}) {
    const double p = chi_square_p(
        axis, [&](double u1, double u2) { return sample_phong_lobe(axis, exponent, u1, u2); },
        [&](const Vec3& w) { return phong_lobe_pdf(axis, exponent, w); });
    EXPECT_GT(p, kSignificance) << "exponent " << exponent;
  }
}

TEST(LightSampling, UniformConeFollowsItsDensity) {
  const Vec3 axis = normalize(Vec3{-0.7, 0.1, -0.3});
  for (double cos_max : {-1.0, 0.0, 0.75, 11.0 / 12}) {  // the cone's edge on a bin edge
    const double p = chi_square_p(
        axis, [&](double u1, double u2) { return sample_uniform_cone(axis, cos_max, u1, u2); },
        [&](const Vec3& w) { return uniform_cone_pdf(axis, cos_max, w); });
    EXPECT_GT(p, kSignificance) << "cos_max " << cos_max;
  }
}

// The test has power: a cone sampler with the wrong density (uniform in angle) fails it.
TEST(LightSampling, ChiSquareRejectsAWrongDensity) {
  const Vec3 axis{0, 0, 1};
  const double p = chi_square_p(
      axis,
      [&](double u1, double u2) -> std::optional<Vec3> {
        const double theta = u1 * kPi / 3, phi = 2 * kPi * u2;
        return Vec3{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                    std::cos(theta)};
      },
      [&](const Vec3& w) { return uniform_cone_pdf(axis, 0.5, w); });
  EXPECT_LT(p, 1e-9);
}

Material glossy(double diffuse, double specular, double exponent) {
  Material m;
  m.diffuse = {diffuse, diffuse * 0.8, diffuse * 0.5};
  m.specular = {specular, specular, specular};
  m.shininess = exponent;
  return m;
}

// Smooth lobes: the directions sample_bsdf returns follow bsdf_evaluate's density, and the
// rejected ones (below the surface) match the density's missing mass.
TEST(LightSampling, BsdfSamplesFollowBsdfPdf) {
  const Vec3 n = normalize(Vec3{0.1, 0.3, 0.9});
  for (const Material& m : {glossy(0.6, 0.3, 20), glossy(0.0, 0.9, 5), glossy(0.8, 0.0, 1)})
    for (const Vec3& wo : {n, normalize(Vec3{0.8, 0.0, 0.3})}) {
      uint32_t lobe_state = rng_seed(4, 5, 6);
      const double p = chi_square_p(
          n,
          [&](double u1, double u2) -> std::optional<Vec3> {
            const auto s = sample_bsdf(m, n, wo, true, rng_next(lobe_state), u1, u2);
            if (!s) return std::nullopt;
            return s->wi;
          },
          [&](const Vec3& w) { return bsdf_evaluate(m, n, wo, w).pdf; });
      EXPECT_GT(p, kSignificance) << "specular " << m.specular.x << " wo.z " << wo.z;
    }
}

// Directional albedo: the mean sample weight. At most the lobe weights' sum for every w_o,
// and Lambert alone reflects exactly its albedo.
TEST(LightSampling, BsdfConservesEnergy) {
  const Vec3 n{0, 0, 1};
  for (const Material& m : {glossy(0.5, 0.5, 1), glossy(0.3, 0.7, 30), glossy(1.0, 0.0, 1)})
    for (double cos_o : {1.0, 0.7, 0.3, 0.05}) {
      const Vec3 wo{std::sqrt(1 - cos_o * cos_o), 0, cos_o};
      uint32_t state = rng_seed(9, 8, 7);
      constexpr int kN = 200000;
      Vec3 albedo;
      for (int i = 0; i < kN; ++i) {
        const double u0 = rng_next(state), u1 = rng_next(state), u2 = rng_next(state);
        if (const auto s = sample_bsdf(m, n, wo, true, u0, u1, u2)) albedo += s->weight / kN;
      }
      for (int c = 0; c < 3; ++c) EXPECT_LE(albedo[c], m.diffuse[c] + m.specular[c] + 0.01);
      if (m.specular.x == 0) EXPECT_NEAR(albedo.x, m.diffuse.x, 0.01);
    }
}

TEST(LightSampling, BsdfIsReciprocal) {
  const Vec3 n = normalize(Vec3{0.2, 0.1, 1});
  const Material m = glossy(0.4, 0.5, 12);
  uint32_t state = rng_seed(1, 1, 1);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 a = sample_cosine_hemisphere(n, rng_next(state), rng_next(state));
    const Vec3 b = sample_cosine_hemisphere(n, rng_next(state), rng_next(state));
    const Vec3 fab = bsdf_evaluate(m, n, a, b).f, fba = bsdf_evaluate(m, n, b, a).f;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(fab[c], fba[c], 1e-12 * (1 + fab[c]));
  }
}

// Dielectric: energy is conserved exactly (reflection and refraction weights are the lobe
// weight, up to the 1/eta^2 radiance scaling), refraction obeys Snell's law, and total
// internal reflection happens past the critical angle.
TEST(LightSampling, DielectricRefractsBySnellsLaw) {
  Material glass;
  glass.transmission = {1, 1, 1};
  glass.ior = 1.5;
  const Vec3 n{0, 0, 1};
  for (double cos_o : {1.0, 0.8, 0.3}) {
    const Vec3 wo{std::sqrt(1 - cos_o * cos_o), 0, cos_o};
    const auto refracted = sample_bsdf(glass, n, wo, true, 0.999999, 0.5, 0.5);
    ASSERT_TRUE(refracted && refracted->transmitted);
    const double sin_o = std::sqrt(1 - cos_o * cos_o);
    const double sin_t = std::sqrt(1 - refracted->wi.z * refracted->wi.z);
    EXPECT_NEAR(sin_o, 1.5 * sin_t, 1e-12);
    EXPECT_LT(refracted->wi.z, 0);
    EXPECT_NEAR(refracted->weight.x, 1 / (1.5 * 1.5), 1e-12);
    const auto reflected = sample_bsdf(glass, n, wo, true, 0.0, 0.5, 0.5);
    ASSERT_TRUE(reflected && !reflected->transmitted);
    EXPECT_NEAR(length(reflected->wi - Vec3{-wo.x, 0, wo.z}), 0, 1e-12);
  }
  // From inside at 60 degrees: sin 60 * 1.5 > 1, every sample reflects.
  const Vec3 inside{std::sqrt(0.75), 0, 0.5};
  for (double u0 : {0.0, 0.5, 0.999999})
    EXPECT_FALSE(sample_bsdf(glass, n, inside, false, u0, 0.5, 0.5)->transmitted);
  EXPECT_NEAR(fresnel_dielectric(1.0, 1.5), 0.04, 1e-12);
}

// The cone a geodesic sphere subtends, sin(alpha) = sqrt(A(r) / A(d)): the geodesic leaving
// x at angle alpha from the centre's direction touches the sphere (double root).
TEST(LightSampling, SphereConeGrazesTheSphere) {
  for (GeometryKind k : kKinds) {
    const Vec4 x = model::origin();
    const Vec4 c = model::exp_origin(k, {0.3, -0.2, 1.1});
    const double d = model::geodesic_distance(k, x, c), r = 0.35;
    const double sin_alpha = std::sqrt(model::sphere_area_factor(k, r) / model::sphere_area_factor(k, d));
    const Vec4 toward = model::geodesic_direction(k, x, c);
    const Vec3 axis = toward.xyz(), side = normalize(cross(axis, Vec3{1, 0, 0}));
    const double cos_alpha = std::sqrt(1 - sin_alpha * sin_alpha);
    const Vec4 v{cos_alpha * axis + sin_alpha * side, 0};
    const model::SphereRoots roots = model::sphere_roots(k, x, v, c, r);
    EXPECT_NEAR(roots.disc, 0, 1e-12) << geometry_name(k);
    const Vec4 inside{std::cos(0.99 * std::asin(sin_alpha)) * axis +
                          std::sin(0.99 * std::asin(sin_alpha)) * side, 0};
    EXPECT_GT(model::sphere_roots(k, x, inside, c, r).disc, 0) << geometry_name(k);
  }
}

// The cone a horoball subtends, sin(alpha) = 1 / -<x, l>, about the tangent towards its ideal
// point: geodesics from x just inside it meet the horosphere (the shape's double twin), just
// outside they miss it, from points near and far and at the horosphere's own distance e^-d; from
// inside the horoball every direction meets it.
TEST(LightSampling, HorosphereConeGrazesTheHorosphere) {
  constexpr auto k = GeometryKind::Hyperbolic;
  const ShapeKind& horosphere = shape_kind(SHAPE_HOROSPHERE);
  for (const Vec3& at : {Vec3{0, 0, 0}, Vec3{0.2, -0.4, 0.3}, Vec3{-1.5, 0.8, -2.0}})
    for (double d : {0.05, 0.7, 3.0}) {
      ShapeParams s;
      s.a = std::exp(d) * Vec4(normalize(Vec3{0.3, 0.9, -0.2}), 1);
      const Vec4 x = model::exp_origin(k, at);
      const double cos_alpha = horosphere_cone_cos(x, s.a);
      if (at.x == 0) EXPECT_NEAR(cos_alpha, std::sqrt(1 - std::exp(-2 * d)), 1e-12);
      ASSERT_GT(cos_alpha, -1) << "x is outside the horoball";
      const Vec4 axis = model::normalize_tangent(k, x, s.a + model::inner(k, x, s.a) * x);
      // A unit tangent at x orthogonal to the axis.
      Vec4 side = model::normalize_tangent(k, x, Vec4{1, 0, 0, 0} + model::inner(k, x, Vec4{1, 0, 0, 0}) * x);
      side = model::normalize_tangent(k, x, side - model::inner(k, side, axis) * axis);
      const double alpha = std::acos(cos_alpha);
      for (double f : {0.999, 1.001}) {
        const Vec4 v = std::cos(f * alpha) * axis + std::sin(f * alpha) * side;
        const double t = horosphere.intersect(k, s, x, v, 0, INFINITY);
        EXPECT_EQ(std::isfinite(t), f < 1) << "x " << at.x << ", d " << d << ", f " << f;
      }
    }
  ShapeParams inside;
  inside.a = std::exp(-0.4) * Vec4(0, 0, 1, 1);
  const Vec4 x = model::origin();
  EXPECT_EQ(horosphere_cone_cos(x, inside.a), -1);
  // (All but the one geodesic that runs into the ideal point and never leaves.)
  for (const Vec3& w : {normalize(Vec3{0.01, 0, 1}), Vec3{0, 0, -1}, Vec3{1, 0, 0}, Vec3{0.6, -0.8, 0}})
    EXPECT_TRUE(std::isfinite(horosphere.intersect(k, inside, x, Vec4(w, 0), 0, INFINITY))) << w.x;
}

// The area Jacobian integrates to the triangle's area (angle defect in H3, excess in S3).
TEST(LightSampling, TriangleJacobianIntegratesToItsArea) {
  for (GeometryKind k : kKinds) {
    const Vec4 p[3] = {model::exp_origin(k, {0.9, 0.1, -0.2}), model::exp_origin(k, {-0.3, 0.8, 0.1}),
                       model::exp_origin(k, {0.1, -0.6, 0.7})};
    const Vec4 centroid = model::normalize_point(k, p[0] + p[1] + p[2]);
    const Mat4 to_origin = model::translation_from(k, centroid);
    Vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = model::chart(k, to_origin * p[i]);
    constexpr int kSteps = 400;
    double integral = 0;
    for (int i = 0; i < kSteps; ++i)
      for (int j = 0; i + j < kSteps; ++j) {
        // Midpoints of the grid's lower-left triangles, weighted by their barycentric area.
        const double b1 = (i + 1.0 / 3) / kSteps, b2 = (j + 1.0 / 3) / kSteps;
        const Vec3 x = q[0] + b1 * (q[1] - q[0]) + b2 * (q[2] - q[0]);
        integral += triangle_area_jacobian(k, x, q[1] - q[0], q[2] - q[0]) * 0.5 / (kSteps * kSteps);
      }
    // The upper-right triangles of the grid (one fewer per row) complete the area.
    for (int i = 0; i < kSteps; ++i)
      for (int j = 0; i + j < kSteps - 1; ++j) {
        const double b1 = (i + 2.0 / 3) / kSteps, b2 = (j + 2.0 / 3) / kSteps;
        const Vec3 x = q[0] + b1 * (q[1] - q[0]) + b2 * (q[2] - q[0]);
        integral += triangle_area_jacobian(k, x, q[1] - q[0], q[2] - q[0]) * 0.5 / (kSteps * kSteps);
      }
    EXPECT_NEAR(integral, triangle_area(k, p[0], p[1], p[2]), 1e-5 * integral) << geometry_name(k);
  }
}

// A(d) is the square of the spread of nearby geodesics: two leaving the origin at a small
// angle eps are A(d)^(1/2) eps apart at distance d, so the geodesic sphere's area is
// 4 pi A(d) and a point source's irradiance falls off as 1 / A(d).
TEST(LightSampling, SphereAreaFactorIsTheSquaredGeodesicSpread) {
  constexpr double kEps = 1e-6;
  for (GeometryKind k : kKinds)
    for (double d : {0.1, 0.7, 1.5, 2.5}) {
      const Vec4 a = model::exp_origin(k, {d, 0, 0});
      const Vec4 b = model::exp_origin(k, {d * std::cos(kEps), d * std::sin(kEps), 0});
      const double spread = model::geodesic_distance(k, a, b) / kEps;
      EXPECT_NEAR(spread * spread, model::sphere_area_factor(k, d),
                  1e-6 * model::sphere_area_factor(k, d))
          << geometry_name(k) << " d " << d;
    }
}

}  // namespace
}  // namespace geodesic
