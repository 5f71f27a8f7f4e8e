// The float GLSL geometry, sampling, BSDF and random-number routines held against their double
// C++ twins, in all three model geometries, through shaders/probes/geometry_probe.comp
// (compiled per geometry). geometry_probe.h states the tolerance: each output within a few
// float ulps of what its inputs' rounding allows. The worst errors are printed per routine.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/random.h"
#include "geometry/sobol.h"
#include "geometry/sampling.h"
#include "geometry_probe.h"
#include "twins/bsdf.h"
#include "test_constants.h"

namespace geodesic::test {
namespace {


class GlslReference : public ::testing::TestWithParam<GeometryKind> {
 protected:
  GeometryKind k = GetParam();
  bool spherical = k == GeometryKind::Spherical;
  ProbeCaseMaker maker{k, 20240611};
};

// Each routine of geometry/model.glsl: its inputs in a probe case, its double twin, and its
// output in the probe result. The tolerance (geometry_probe.h): 16 u (S + |f|), plus an
// absolute 1e-6 for routines through sin/cos/exp/log, whose precision is absolute near their
// zeros (lavapipe: sin, cos within 2 ulps, exp 8, log 1.4e-7 absolute near 1). 64 u for the
// unit-tangent routines: in H3 the form sums squares of size |p|^2 |v|^2 to reach 1, and their
// round-off (about 4 u each) is not an input perturbation. 32 u for S3's translation, whose
// w < 0 branch chains a length, a division and a product.
struct Routine {
  Agreement agreement;
  std::function<Values(const ProbeCase&)> inputs;
  std::function<Values(const Values&)> reference;
  std::function<Values(const ProbeResult&)> glsl;
};

std::vector<Routine> routines(GeometryKind k) {
  const double ulps = 16, trig = k == GeometryKind::Euclidean ? 0 : 1e-6;
  const double tangents = 64, translation = 32;
  const auto in = [](auto... fields) {
    return [=](const ProbeCase& c) { return values(fields(c)...); };
  };
  const auto p = [](const ProbeCase& c) { return v4(c.point); };
  const auto v = [](const ProbeCase& c) { return v4(c.tangent); };
  const auto q = [](const ProbeCase& c) { return v4(c.target); };
  const auto t = [](const ProbeCase& c) { return double(c.params[0]); };
  const auto loose = [](const ProbeCase& c) { return v4(c.loose); };
  const auto out = [](F4 ProbeResult::*field, int n = 4) {
    return [=](const ProbeResult& r) { return floats(r.*field, n); };
  };
  const auto matrix = [](F16 ProbeResult::*field) {
    return [=](const ProbeResult& r) { return floats(r.*field); };
  };
  const auto scalar = [](F4 ProbeResult::*field, int i) {
    return [=](const ProbeResult& r) { return Values{(r.*field)[i]}; };
  };
  using V3 = Vec3;
  using V4 = Vec4;
  using R = ProbeResult;
  return {
      {{"geodesicPoint", ulps, trig}, in(p, v, t),
       twin<V4, V4, double>(k, model::geodesic_point), out(&R::geodesic)},
      {{"geodesicTangent", ulps, trig}, in(p, v, t),
       twin<V4, V4, double>(k, model::geodesic_tangent), out(&R::velocity)},
      {{"geodesicDistance", ulps, trig}, in(p, q),
       twin<V4, V4>(k, model::geodesic_distance), scalar(&R::scalars, 1)},
      {{"areaFactorBetween", ulps}, in(p, q), twin<V4, V4>(k, model::area_factor_between),
       scalar(&R::areas, 0)},
      {{"sphereAreaFactor(geodesicDistance)", ulps, trig}, in(p, q),
       [k](const Values& x) {
         return Values{model::sphere_area_factor(
             k, model::geodesic_distance(k, {x[0], x[1], x[2], x[3]}, {x[4], x[5], x[6], x[7]}))};
       },
       scalar(&R::areas, 1)},
      {{"geodesicDirection", tangents}, in(p, q),
       twin<V4, V4>(k, model::geodesic_direction), out(&R::towards)},
      {{"modelInner", ulps}, in(v, loose), twin<V4, V4>(k, model::inner), scalar(&R::scalars, 2)},
      {{"translationTo", translation}, in(q), twin<V4>(k, model::translation_to),
       matrix(&R::translated_to)},
      {{"translationFrom", translation}, in(q), twin<V4>(k, model::translation_from),
       matrix(&R::translated_from)},
      {{"inverseIsometry", ulps}, in([](const ProbeCase& c) { return from_glsl(c.isometry); }),
       twin<Mat4>(k, model::inverse_isometry), matrix(&R::inverse)},
      {{"chartPlaneNormal", tangents},
       in(p, [](const ProbeCase& c) { return v3(c.plane); },
          [](const ProbeCase& c) { return double(c.plane[3]); }),
       twin<V4, V3, double>(k, model::chart_plane_normal), out(&R::plane_normal)},
      {{"sphereNormal", tangents}, in([](const ProbeCase& c) { return v4(c.sphere); }, q),
       twin<V4, V4>(k, model::sphere_normal), out(&R::sphere_normal)},
      {{"normalizePoint", ulps}, in(loose), twin<V4>(k, model::normalize_point),
       out(&R::normalized_point)},
      {{"normalizeTangent", tangents}, in(p, loose), twin<V4, V4>(k, model::normalize_tangent),
       out(&R::normalized_tangent)},
      {{"chartPoint", ulps}, in(p), twin<V4>(k, model::chart), out(&R::chart_of_point, 3)},
      {{"liftChart", ulps}, in([](const ProbeCase& c) { return v3(c.chart); }),
       twin<V3>(k, model::lift), out(&R::lifted)},
      {{"chartDirection", ulps}, in(p, v), twin<V4, V4>(k, model::chart_direction),
       out(&R::chart_velocity, 3)},
      {{"chartParameter", ulps, trig}, in(p, v, t),
       twin<V4, V4, double>(k, model::chart_parameter), scalar(&R::chart_scalars, 0)},
      {{"distanceFromChartParameter", ulps, trig},
       in(p, v, [](const ProbeCase& c) { return double(c.chart[3]); }),
       twin<V4, V4, double>(k, model::distance_from_chart_parameter),
       scalar(&R::chart_scalars, 1)},
      {{"surfaceOffsetLength", ulps}, in(p), twin<V4>(k, model::surface_offset_length),
       scalar(&R::chart_scalars, 3)},
      {{"offsetFromSurface", ulps, trig}, in(p, v), twin<V4, V4>(k, model::offset_from_surface),
       out(&R::offset)},
      {{"reflectInChartPlane", ulps},
       in(p, [](const ProbeCase& c) { return v3(c.plane); },
          [](const ProbeCase& c) { return double(c.plane[3]); }),
       twin<V4, V3, double>(k, model::reflect_in_chart_plane), out(&R::reflected)},
  };
}

// Random cases, then the edges: the origin, t = 0 and tiny t, a point and itself or a close
// neighbour, H3 points far out, S3 antipodes.
std::vector<ProbeCase> routine_cases(GeometryKind k, ProbeCaseMaker& maker) {
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 4096; ++i) cases.push_back(maker.make());
  const double tiny_t[] = {0, 1e-6, -1e-4, 1e-4, 0.3};
  for (int i = 0; i < 400; ++i) {
    ProbeCase c = maker.make();
    const Vec4 p = i % 4 == 0 ? model::origin()
                   : i % 4 == 1 && k == GeometryKind::Hyperbolic ? maker.rounded(sample.point(6))
                                                                 : v4(c.point);
    const Vec4 v = maker.rounded(sample.tangent(p));
    c.point = f4(p);
    c.tangent = f4(v);
    c.params[0] = float(tiny_t[i % 5]);
    c.chart[3] = float(model::chart_parameter(k, p, v, tiny_t[i % 5]));
    const double near = (i / 5) % 2 ? 1e-5 : 0;
    c.target = f4(model::geodesic_point(k, p, v, near));
    if (k == GeometryKind::Spherical && i % 3 == 0)
      c.target = f4(model::geodesic_point(k, p, v, std::acos(-1.0) - (i % 2 ? 1e-3 : 0)));
    c.sphere = c.target;
    cases.push_back(c);
  }
  return cases;
}

TEST_P(GlslReference, EveryRoutineMatchesItsDoubleTwin) {
  const std::vector<ProbeCase> cases = routine_cases(k, maker);
  const auto results = run_probe(k, cases);
  std::vector<Routine> all = routines(k);
  for (size_t i = 0; i < cases.size(); ++i) {
    const ProbeResult& g = results[i];
    for (Routine& r : all) r.agreement.check(r.glsl(g), r.reference, r.inputs(cases[i]), int(i));
    EXPECT_EQ(g.chart_scalars[2], model::curvature(k));
    EXPECT_EQ(v4(g.origin).w, 1.0f);
    EXPECT_EQ(max_abs(v4(g.origin).xyz()), 0.0);
  }
  std::printf("float GLSL vs double, %zu cases:\n", cases.size());
  for (const Routine& r : all) r.agreement.print(geometry_name(k));
}

TEST_P(GlslReference, RandomNumbersAreBitExact) {  // and the Sobol points and their seeds
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 4096; ++i) cases.push_back(maker.make());
  for (uint32_t edge : {0u, 1u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu}) {
    ProbeCase c = maker.make();
    c.rng = {edge, edge, edge, edge};
    cases.push_back(c);
  }
  const auto results = run_probe(k, cases);
  for (size_t i = 0; i < cases.size(); ++i) {
    const auto& in = cases[i].rng;
    const auto& out = results[i];
    ASSERT_EQ(out.hashes[0], pcg_hash(in[3])) << "case " << i;
    uint32_t state = rng_seed(in[0], in[1], in[2]);
    ASSERT_EQ(out.hashes[1], state) << "case " << i;
    for (int j = 0; j < 4; ++j) ASSERT_EQ(double(out.draws[j]), rng_next(state)) << "case " << i;
    ASSERT_EQ(out.hashes[2], state) << "case " << i;
    // The pixel samples' Sobol points, bit for bit.
    const SobolPoint point = sobol_sample(in[1], in[3]);
    ASSERT_EQ(out.sobol[0], point.x) << "case " << i;
    ASSERT_EQ(out.sobol[1], point.y) << "case " << i;
    ASSERT_EQ(out.sobol[2], nested_uniform_scramble(in[0], in[2])) << "case " << i;
    ASSERT_EQ(out.sobol[3], sobol_second(in[1])) << "case " << i;
    // The seeds of a path's dimension pairs (shaders/common/sampler.glsl).
    ASSERT_EQ(out.path_seeds[0], path_sampler_seed(in[0], in[1] & 1u, in[2] & 15u, in[3])) << "case " << i;
    ASSERT_EQ(out.path_seeds[1], path_sampler_seed(in[0], in[1] & 1u, 0, in[3])) << "case " << i;
    ASSERT_EQ(out.path_seeds[2], path_sampler_seed(in[0], in[1] & 1u, 1, in[3])) << "case " << i;
  }
}

TEST_P(GlslReference, SamplingMatchesWithinOneMillionth) {
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
        c.normal = f4(n, 0);
        c.uv = {u1, u2, 0, 0};
        cases.push_back(c);
      }
  // The power heuristic's two densities: zero, tiny, equal, huge and infinite (a delta lobe).
  const float densities[] = {0.0f, 1e-6f, 0.5f, 1.0f, 3.0f, 1e6f, INFINITY};
  for (size_t i = 0; i < cases.size(); ++i) {
    cases[i].uv[2] = densities[i % 7];
    cases[i].uv[3] = densities[(i / 7) % 7];
  }
  const auto results = run_probe(k, cases);
  for (size_t i = 0; i < cases.size(); ++i) {
    const ProbeCase& c = cases[i];
    const ProbeResult& g = results[i];
    const Vec3 n = v3(c.normal);
    const Barycentrics b = sample_uniform_triangle(c.uv[0], c.uv[1]);
    EXPECT_NEAR(g.triangle_sample[0], b.b1, 1e-6);
    EXPECT_NEAR(g.triangle_sample[1], b.b2, 1e-6);
    EXPECT_NEAR(g.triangle_sample[2], power_heuristic(c.uv[2], c.uv[3]), 1e-6)
        << c.uv[2] << ", " << c.uv[3];
    SCOPED_TRACE("case " + std::to_string(i));
    const TangentFrame frame = orthonormal_basis(n);
    EXPECT_LE(max_abs(v3(g.basis_tangent) - frame.tangent), 1e-6);
    EXPECT_LE(max_abs(v3(g.basis_bitangent) - frame.bitangent), 1e-6);
    EXPECT_LE(max_abs(v3(g.cosine_sample) - sample_cosine_hemisphere(n, c.uv[0], c.uv[1])), 1e-6);
    const double lum = luminance(v3(c.colour));
    EXPECT_NEAR(g.scalars[3], lum, 1e-6 * lum);
  }
}

// bsdfEvaluate against bsdf_evaluate, from the probe's own float directions (w_o the normal,
// w_i its cosine sample), for a mix of diffuse, Phong (exponent e in [1, 64]) and mirror lobes.
// The float cosine between w_i and the mirror direction carries a few ulps, which the Phong
// power multiplies by e: within 1e-6 (1 + e) of the value, 1 added for values near zero.
TEST_P(GlslReference, BsdfMatchesItsTwin) {
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 4096; ++i) cases.push_back(maker.make());
  const auto results = run_probe(k, cases);
  double worst = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const ProbeCase& c = cases[i];
    const Vec3 colour = v3(c.colour), n = v3(c.normal);
    Material m;
    m.diffuse = 0.05 * colour;
    m.specular = 0.04 * Vec3{colour.z, colour.y, colour.x};
    m.shininess = 1 + 63 * double(c.uv[1]);
    m.mirror = 0.01 * Vec3{colour.y, colour.z, colour.x};
    const BsdfValue twin = bsdf_evaluate(m, n, n, v3(results[i].cosine_sample));
    const double scale = 1e-6 * (1 + m.shininess);
    const double values[] = {twin.f.x, twin.f.y, twin.f.z, twin.pdf};
    for (int j = 0; j < 4; ++j) {
      const double error = std::abs(results[i].bsdf[j] - values[j]) / (1 + std::abs(values[j]));
      worst = std::max(worst, error / scale);
      EXPECT_LE(error, scale) << "case " << i << ", output " << j;
    }
  }
  std::printf("  %-10s bsdfEvaluate: worst error %.3g of 1e-6 (1 + e) (1 + |value|)\n",
              geometry_name(k), worst);
}

void print(const char* test, GeometryKind k, const SphereStats& stats) {
  std::printf("  %-10s %s: hits %d, misses %d, band %d; worst |error| %.3g, relative %.3g, "
              "%.3g u (S+|t|)\n", geometry_name(k), test, stats.hits, stats.misses, stats.band,
              stats.worst_error, stats.worst_relative, stats.worst_ulps);
}

SphereStats check_spheres(GeometryKind k, const std::vector<ProbeCase>& cases) {
  const auto results = run_probe(k, cases);
  SphereStats stats;
  for (size_t i = 0; i < cases.size(); ++i)
    EXPECT_TRUE(sphere_agrees(k, cases[i], results[i].scalars[0], stats, 16, 1e-6)) << "case " << i;
  print("well-conditioned spheres", k, stats);
  return stats;
}

// Where the sphere tests put the ray origin or centre: near the model origin, as the renderer
// keeps the camera (H3 coordinates grow like cosh of the distance, and so does round-off).
double near_origin(GeometryKind k) { return k == GeometryKind::Hyperbolic ? 1.5 : reach(k); }

// Rays from p at spheres 1.5 r .. 1.5 r + 3 away (S3: up to pi - 1.5 r): clearly hitting
// (impact angle up to 0.9 of the angular radius), clearly missing (1.1 .. 3 times it), or
// starting inside.
TEST_P(GlslReference, WellConditionedSphereHitsAgree) {
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 6000; ++i) {
    const double r = sample.uniform(0.1, spherical ? 1 : 1.5);  // S3: room for d below
    if (i % 3 == 2) {  // inside: only the exit lies ahead
      const Vec4 c = maker.rounded(sample.point(near_origin(k)));
      const Vec4 p = model::geodesic_point(k, c, sample.tangent(c), sample.uniform(0, 0.9 * r));
      const double angle = sample.uniform(0, kPi);
      cases.push_back(maker.make(aimed(k, sample, maker.rounded(p), c, r, angle)));
      continue;
    }
    const double d = sample.uniform(1.5 * r, spherical ? kPi - 1.5 * r : 1.5 * r + 3);
    const Vec4 p = maker.rounded(sample.point(near_origin(k)));
    const Vec4 c = maker.rounded(model::geodesic_point(k, p, sample.tangent(p), d));
    const double alpha = angular_radius(k, r, d);
    const double angle = i % 3 == 0 ? sample.uniform(0, 0.9) * alpha
                                    : std::min(sample.uniform(1.1, 3) * alpha, kPi / 2);
    cases.push_back(maker.make(aimed(k, sample, p, c, r, angle)));
  }
  const SphereStats stats = check_spheres(k, cases);
  EXPECT_EQ(stats.band, 0);
  EXPECT_GT(stats.hits, 3500);
}

// Impact angles alpha (1 + eta) around the angular radius: outside a band of |eta| >= 1e-3
// float must decide hit or miss correctly; inside it only within the tolerance band.
TEST_P(GlslReference, GrazingRaysDisagreeOnlyInsideTheBand) {
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  std::vector<double> etas;
  for (int i = 0; i < 6000; ++i) {
    const double r = sample.uniform(0.1, spherical ? 1 : 1.5);
    const double d = sample.uniform(1.5 * r, spherical ? kPi - 1.5 * r : 1.5 * r + 3);
    const Vec4 p = maker.rounded(sample.point(near_origin(k)));
    const Vec4 c = maker.rounded(model::geodesic_point(k, p, sample.tangent(p), d));
    const double eta = i % 15 == 0 ? 0.0 : (i % 2 ? 1 : -1) * std::pow(10.0, -1 - (i % 7));
    cases.push_back(maker.make(aimed(k, sample, p, c, r, angular_radius(k, r, d) * (1 + eta))));
    etas.push_back(eta);
  }
  const auto results = run_probe(k, cases);
  SphereStats stats;
  for (size_t i = 0; i < cases.size(); ++i) {
    const float t = results[i].scalars[0];
    EXPECT_TRUE(sphere_agrees(k, cases[i], t, stats, 16, 1e-6)) << "case " << i;
    if (std::abs(etas[i]) >= 1e-3) {
      EXPECT_EQ(t != -1.0f, etas[i] < 0) << "case " << i;
    }
  }
  print("grazing rays", k, stats);
  EXPECT_GT(stats.hits, 2000);
}

// Secondary rays from offsetFromSurface's spawn point (tMin = 0, as the renderer traces):
// rays leaving the surface do not hit it again nearby (S3: a geodesic that left comes round
// and meets the sphere again, but not before 1e-2), rays into it find the far side.
TEST_P(GlslReference, RaysLeavingTheSurfaceDoNotHitItAgain) {
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  std::vector<double> outward;
  for (int i = 0; i < 4096; ++i) {
    const double r = sample.uniform(0.1, spherical ? 1.4 : 3);
    const Vec4 c = maker.rounded(sample.point(near_origin(k)));
    const Vec4 n0 = sample.tangent(c);
    const Vec4 q = model::geodesic_point(k, c, n0, r);
    const Vec4 n = model::geodesic_tangent(k, c, n0, r);  // the outward normal at q
    const Vec4 spawn = maker.rounded(model::offset_from_surface(k, q, n));
    const Vec4 d = sample.tangent(q);  // carried along with the spawn point
    const Vec4 moved = model::parallel_transport(k, q, n, model::surface_offset_length(k, q), d);
    ProbeCase pc = maker.make();
    pc.point = f4(spawn);
    pc.tangent = f4(model::normalize_tangent(k, spawn, moved));
    pc.sphere = f4(c);
    pc.params = {0, float(r), 0, kFar};
    cases.push_back(pc);
    outward.push_back(model::inner(k, d, n));
  }
  const auto results = run_probe(k, cases);
  SphereStats stats;
  for (size_t i = 0; i < cases.size(); ++i) {
    const float t = results[i].scalars[0];
    EXPECT_TRUE(sphere_agrees(k, cases[i], t, stats, 16, 1e-6)) << "case " << i;
    if (outward[i] > 1e-3) {
      EXPECT_TRUE(t == -1.0f || t > 1e-2) << "case " << i << ": " << t;
    }
  }
  print("rays leaving the surface", k, stats);
  EXPECT_GT(stats.hits, 1800);
}

// A sphere of radius 0.5 at 1e3..1e4 in E3: the closest-approach discriminant keeps every hit a
// hit, within 8 ulps of the distance.
TEST(GlslReferenceEuclidean, FarSphereErrorStaysWithinAFewUlpsOfDistance) {
  const GeometryKind k = GeometryKind::Euclidean;
  ProbeCaseMaker maker(k, 3);
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 4096; ++i) {
    const Vec4 p = maker.rounded(sample.point(1));
    const double d = std::pow(10.0, sample.uniform(3, 4));
    const Vec4 c = maker.rounded(model::geodesic_point(k, p, sample.tangent(p), d));
    const double angle = sample.uniform(0, 0.9) * angular_radius(k, 0.5, d);
    cases.push_back(maker.make(aimed(k, sample, p, c, 0.5, angle)));
  }
  const auto results = run_probe(k, cases);
  SphereStats stats;
  double worst_ulps_of_distance = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const float t = results[i].scalars[0];
    EXPECT_TRUE(sphere_agrees(k, cases[i], t, stats, 16, 0)) << "case " << i;
    const float d = float(length(v3(cases[i].point) - v3(cases[i].sphere)));
    const auto ref = model::intersect_sphere(k, v4(cases[i].point), v4(cases[i].tangent),
                                             v4(cases[i].sphere), 0.5, 0, kFar);
    if (ref && t != -1.0f)
      worst_ulps_of_distance = std::max(worst_ulps_of_distance,
                                        std::abs(t - *ref) / (std::nextafter(d, kFar) - d));
  }
  EXPECT_EQ(stats.band, 0);
  EXPECT_EQ(stats.hits, 4096);
  EXPECT_LE(worst_ulps_of_distance, 8);
}

INSTANTIATE_TEST_SUITE_P(AllGeometries, GlslReference,
                         ::testing::Values(GeometryKind::Euclidean, GeometryKind::Hyperbolic,
                                           GeometryKind::Spherical),
                         geometry_label);

}  // namespace
}  // namespace geodesic::test
