// The geometry probe (shaders/probes/geometry_probe.comp) seen from C++: its std430 structs,
// a runner per model geometry, random inputs on each model, and the float tolerance each
// output is held to against its double twin in server/geometry/model.h.
//
// Tolerance: the inputs are rounded to float first and the reference reads them back, so the
// reference sees exactly the shader's inputs. A float routine is then as good as its inputs
// allow when every output f differs from the double reference by at most
//   ulps * u * (S + |f|) + floor,   u = 2^-24,   S = sum_j |df/dx_j| |x_j|,
// S being the first-order change of f when every input x_j moves by a relative u, over u (the
// componentwise condition of the double formula on these inputs, by central differences).
// `ulps` absorbs the handful of roundings inside each routine; `floor` the absolute error the
// Vulkan precision rules allow transcendental built-ins.
#pragma once

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "../unit/model_sampler.h"
#include "geometry/model.h"
#include "probe_runner.h"
#include "render_fixture.h"

namespace geodesic::test {

using F4 = std::array<float, 4>;
using F16 = std::array<float, 16>;

struct ProbeCase {
  F16 isometry;
  F4 point, tangent, target, sphere, loose, params, plane, chart, normal, colour, uv;
  std::array<uint32_t, 4> rng;
  F4 capsule_a, capsule_b;  // a capsule (xyz, radius) and (xyz, sMax) for intersectCapsule
  F4 shape_a, shape_b, shape_size;  // a shape's vectors; (size, tMax) for intersectShape
  std::array<uint32_t, 4> shape_kind;  // x: its kind (shaders/common/shape_kinds.h)
  F4 triangle_a, triangle_b, triangle_c;  // corners; triangle_a[3]: sMax (intersectChartTriangle)
};
static_assert(sizeof(ProbeCase) == 64 + 11 * 16 + 16 + 2 * 16 + 4 * 16 + 3 * 16);

struct ProbeResult {
  F4 scalars, chart_scalars, origin, geodesic, velocity, towards;
  F16 translated_to, translated_from, inverse;
  F4 plane_normal, sphere_normal, normalized_point, normalized_tangent, chart_of_point, lifted,
      chart_velocity, offset, basis_tangent, basis_bitangent, cosine_sample;
  std::array<uint32_t, 4> hashes;
  F4 draws, reflected, triangle_sample, capsule, areas;
  std::array<uint32_t, 4> sobol, path_seeds;
  F4 bsdf;
  F4 shape_hit, shape_normal;  // intersectShape(shape, p, v, 0, tMax); shapeNormal(shape, q)
  F4 triangle;  // intersectChartTriangle: s (kFar: none), u, v
  F4 parallelogram;  // intersectChartParallelogram on the triangle's corners: s (kFar), alpha, beta
};
static_assert(sizeof(ProbeResult) == 6 * 16 + 3 * 64 + 11 * 16 + 9 * 16 + 4 * 16);

constexpr double kUnitRoundoff = FLT_EPSILON / 2;
constexpr float kFar = 1e30f;

inline std::vector<ProbeResult> run_probe(GeometryKind k, const std::vector<ProbeCase>& cases) {
  ProbeRunner runner(device(), "probes/geometry_probe.comp", k);
  return runner.run<ProbeResult>(cases);
}

inline F4 f4(const Vec4& v) { return {float(v.x), float(v.y), float(v.z), float(v.w)}; }
inline F4 f4(const Vec3& v, double w) { return f4(Vec4(v, w)); }
inline Vec4 v4(const F4& f) { return {f[0], f[1], f[2], f[3]}; }
inline Vec3 v3(const F4& f) { return {f[0], f[1], f[2]}; }
inline Mat4 from_glsl(const F16& column_major) {
  Mat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m.m[r][c] = column_major[c * 4 + r];
  return m;
}

// Routine inputs and outputs as flat lists, for the sensitivity's finite differences.
using Values = std::vector<double>;
inline void append(Values& x, const Vec4& v) { x.insert(x.end(), {v.x, v.y, v.z, v.w}); }
inline void append(Values& x, const Vec3& v) { x.insert(x.end(), {v.x, v.y, v.z}); }
inline void append(Values& x, const Mat4& g) {
  for (const auto& row : g.m) x.insert(x.end(), row.begin(), row.end());
}
inline void append(Values& x, double s) { x.push_back(s); }
template <typename... T>
Values values(const T&... parts) {
  Values x;
  (append(x, parts), ...);
  return x;
}
// Reads a flat list back in order.
class Unpack {
 public:
  explicit Unpack(const Values& x) : x_(x) {}
  template <typename T>
  T get() {
    if constexpr (std::is_same_v<T, double>) {
      return x_[i_++];
    } else if constexpr (std::is_same_v<T, Vec3>) {
      return Vec3{get<double>(), get<double>(), get<double>()};
    } else if constexpr (std::is_same_v<T, Vec4>) {
      return Vec4{get<double>(), get<double>(), get<double>(), get<double>()};
    } else {
      Mat4 g;
      for (auto& row : g.m)
        for (double& e : row) e = get<double>();
      return g;
    }
  }

 private:
  const Values& x_;
  size_t i_ = 0;
};

// The double twin f(k, args...) of a routine as a function of its flat inputs.
template <typename... Args, typename Twin>
std::function<Values(const Values&)> twin(GeometryKind k, Twin f) {
  return [k, f](const Values& x) {
    Unpack in(x);
    const std::tuple<Args...> args{in.get<Args>()...};  // braces read left to right
    return std::apply([&](const Args&... a) { return values(f(k, a...)); }, args);
  };
}

// S for each output of f at x (see the header comment).
template <typename F>
Values input_sensitivity(const F& f, const Values& x) {
  constexpr double kStep = 1e-7;  // relative
  Values s(f(x).size(), 0.0);
  Values moved = x;
  for (size_t j = 0; j < x.size(); ++j) {
    if (x[j] == 0) continue;  // rounding leaves a zero input exact
    moved[j] = x[j] * (1 + kStep);
    const Values up = f(moved);
    moved[j] = x[j] * (1 - kStep);
    const Values down = f(moved);
    moved[j] = x[j];
    // Undefined once an input moves by 1e-7: as ill-conditioned as can be.
    for (size_t i = 0; i < s.size(); ++i) {
      const double change = std::abs(up[i] - down[i]) / (2 * kStep);
      s[i] += std::isfinite(change) ? change : INFINITY;
    }
  }
  return s;
}

// One routine's float outputs against the double reference over many cases: asserts the
// tolerance and keeps the worst absolute error and the worst in units of u (S + |f|).
class Agreement {
 public:
  Agreement(std::string name, double ulps, double floor = 0)
      : name_(std::move(name)), ulps_(ulps), floor_(floor) {}

  template <typename F>
  void check(const Values& glsl, const F& reference, const Values& inputs, int case_index) {
    const Values ref = reference(inputs), s = input_sensitivity(reference, inputs);
    for (size_t i = 0; i < ref.size(); ++i) {
      const double error = std::abs(glsl[i] - ref[i]);
      const double scale = kUnitRoundoff * (s[i] + std::abs(ref[i]));
      EXPECT_LE(error, ulps_ * scale + floor_)
          << name_ << " case " << case_index << " output " << i << ": glsl " << glsl[i]
          << " reference " << ref[i] << " sensitivity " << s[i];
      worst_error_ = std::max(worst_error_, error);
      if (error > floor_) worst_ulps_ = std::max(worst_ulps_, (error - floor_) / scale);
    }
  }
  void print(const char* geometry) const {
    std::printf("  %-10s %-26s worst |error| %9.3g, beyond the floor %6.3g u (S+|f|)"
                "  (bound %g u (S+|f|) + %g)\n",
                geometry, name_.c_str(), worst_error_, worst_ulps_, ulps_, floor_);
  }

 private:
  std::string name_;
  double ulps_, floor_;
  double worst_error_ = 0, worst_ulps_ = 0;
};

inline Values floats(const F4& f, int n = 4) { return Values(f.begin(), f.begin() + n); }
inline Values floats(const F16& column_major) {
  return values(from_glsl(column_major));
}

// intersectGeodesicSphere against intersect_sphere on the same inputs. The discriminant and
// both roots get the Agreement tolerance (ulps u (S + |f|) + floor); hit or miss, and which
// root, may differ only inside that band: |disc| within its tolerance, or a root (S3: modulo
// 2 pi) within its tolerance of tMin or tMax.
struct SphereStats {
  int hits = 0;         // both hit, within the tolerance
  int misses = 0;       // both miss
  int band = 0;         // disagreements inside the band
  double worst_error = 0, worst_relative = 0, worst_ulps = 0;  // over agreeing hits
};

inline ::testing::AssertionResult sphere_agrees(GeometryKind k, const ProbeCase& c, float glsl,
                                                SphereStats& stats, double ulps, double floor) {
  const Vec4 p = v4(c.point), v = v4(c.tangent), centre = v4(c.sphere);
  const double r = c.params[1], t_min = c.params[2], t_max = c.params[3];
  const auto roots_of = [k](const Values& x) {
    Unpack in(x);
    const Vec4 a = in.get<Vec4>(), b = in.get<Vec4>(), o = in.get<Vec4>();
    const auto s = model::sphere_roots(k, a, b, o, in.get<double>());
    return Values{s.disc, s.t0, s.t1};
  };
  const Values x = values(p, v, centre, r);
  const Values roots = roots_of(x), sensitivity = input_sensitivity(roots_of, x);
  Values tol(3);
  for (int i = 0; i < 3; ++i)
    tol[i] = ulps * kUnitRoundoff * (sensitivity[i] + std::abs(roots[i])) + floor;
  // Distance between two arc lengths on this geodesic (S3: it closes after 2 pi).
  const auto apart = [k](double a, double b) {
    return k == GeometryKind::Spherical ? std::abs(std::remainder(a - b, 2 * std::acos(-1.0)))
                                        : std::abs(a - b);
  };

  const auto ref = model::intersect_sphere(k, p, v, centre, r, t_min, t_max);
  const bool glsl_hit = glsl != -1.0f;
  if (glsl_hit && ref) {
    const int j = apart(*ref, roots[1]) <= apart(*ref, roots[2]) ? 1 : 2;
    const double error = std::abs(glsl - *ref);
    if (error <= tol[j]) {
      ++stats.hits;
      stats.worst_error = std::max(stats.worst_error, error);
      stats.worst_relative = std::max(stats.worst_relative, error / std::max(*ref, 1e-30));
      stats.worst_ulps = std::max(
          stats.worst_ulps, error / (kUnitRoundoff * (sensitivity[j] + std::abs(roots[j]))));
      return ::testing::AssertionSuccess();
    }
  } else if (glsl_hit == ref.has_value()) {
    ++stats.misses;
    return ::testing::AssertionSuccess();
  }
  bool in_band = std::abs(roots[0]) <= tol[0];
  for (int j = 1; j <= 2 && roots[0] >= 0; ++j)
    in_band = in_band || apart(roots[j], t_min) <= tol[j] || apart(roots[j], t_max) <= tol[j];
  if (in_band) {
    ++stats.band;
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "glsl " << glsl << " vs reference " << (ref ? *ref : -1.0) << " (disc " << roots[0]
         << " +- " << tol[0] << ", roots " << roots[1] << " +- " << tol[1] << ", " << roots[2]
         << " +- " << tol[2] << ")";
}

// The angle under which a sphere of radius r at distance d appears: sin alpha = r / d (E3),
// sinh r / sinh d (H3), sin r / sin d (S3); pi/2 from inside.
inline double angular_radius(GeometryKind k, double r, double d) {
  double sin_alpha = r / d;
  if (k == GeometryKind::Hyperbolic) sin_alpha = std::sinh(r) / std::sinh(d);
  if (k == GeometryKind::Spherical) sin_alpha = std::sin(r) / std::sin(d);
  return std::asin(std::min(1.0, sin_alpha));
}

// A ray at a sphere, exact (double) until a probe case rounds it to float, with its first hit
// computed in double from the exact values (-1: none).
struct Shot {
  Vec4 p, v, c;
  double r;
  double exact;
};

inline Shot shot(GeometryKind k, const Vec4& p, const Vec4& v, const Vec4& c, double r) {
  return {p, v, c, r, model::intersect_sphere(k, p, v, c, r, 0, kFar).value_or(-1)};
}

// The ray from p at the sphere (c, r) tilted by `angle` from the direction to c.
inline Shot aimed(GeometryKind k, ModelSampler& sample, const Vec4& p, const Vec4& c, double r,
                  double angle) {
  const Vec4 e = model::geodesic_direction(k, p, c), f = sample.perpendicular(p, e);
  return shot(k, p, std::cos(angle) * e + std::sin(angle) * f, c, r);
}

// How far each model reaches in the random cases: E3 a box of 10, H3 distance 3 (coordinates
// up to cosh 3 ~ 10), S3 all of it.
inline double reach(GeometryKind k) {
  switch (k) {
    case GeometryKind::Hyperbolic: return 3;
    case GeometryKind::Spherical: return 3.1;
    default: return 10;
  }
}

// Random inputs on one model, every field valid for its routine; tests override fields.
class ProbeCaseMaker {
 public:
  ProbeCaseMaker(GeometryKind k, uint64_t seed) : k_(k), sample_(k, seed), gen_(seed) {}
  ModelSampler& sample() { return sample_; }

  ProbeCase make() {
    const double r = reach(k_);
    const Vec4 p = rounded(sample_.point(r));
    ProbeCase c{};
    c.isometry = sample_.isometry(r).to_glsl();
    c.point = f4(p);
    c.tangent = f4(sample_.tangent(p));
    c.target = f4(sample_.point(r));
    c.sphere = f4(sample_.point(r));
    // Near p and near a tangent: what the renderer normalises after float isometries.
    c.loose = f4(sample_.uniform(0.9, 1.1) * p + sample_.uniform(-2, 2) * sample_.tangent(p));
    const double t = sample_.uniform(-r, r);
    c.params = {float(t), float(sample_.uniform(0.1, 3)), 0, kFar};
    const double delta = sample_.uniform(-0.9, 0.9) * (k_ == GeometryKind::Hyperbolic ? 1 : 3);
    c.plane = f4(sample_.unit3(), delta);
    const Vec3 x = k_ == GeometryKind::Hyperbolic ? sample_.ball(0.95) : sample_.ball(r);
    const Vec4 v = v4(c.tangent);
    c.chart = f4(x, model::chart_parameter(k_, p, v, sample_.uniform(-1, 1)));
    c.normal = f4(sample_.unit3(), 0);
    c.colour = f4(Vec3{sample_.uniform(0, 10), sample_.uniform(0, 10), sample_.uniform(0, 10)}, 0);
    c.uv = {float(sample_.uniform(0, 1)), float(sample_.uniform(0, 1)), 0, 0};
    for (auto& word : c.rng) word = uint32_t(gen_());
    return c;
  }

  // A random case carrying the sphere shot, tMin = 0, tMax = kFar.
  ProbeCase make(const Shot& s) {
    ProbeCase c = make();
    c.point = f4(s.p);
    c.tangent = f4(s.v);
    c.sphere = f4(s.c);
    c.params = {0, float(s.r), 0, kFar};
    return c;
  }

  // v rounded to float, as the probe will see it.
  Vec4 rounded(const Vec4& v) const { return v4(f4(v)); }

 private:
  GeometryKind k_;
  ModelSampler sample_;
  std::mt19937_64 gen_;
};

}  // namespace geodesic::test
