// Random points, unit tangents and isometries of a model geometry, and how far a point or a
// frame has drifted off the model: shared by the model and numerics unit tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "geometry/model.h"

namespace geodesic::test {

inline double max_abs(const Mat4& g) {
  double m = 0;
  for (const auto& row : g.m)
    for (double x : row) m = std::max(m, std::abs(x));
  return m;
}
inline Mat4 difference(const Mat4& a, const Mat4& b) {
  Mat4 d;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) d.m[i][j] = a.m[i][j] - b.m[i][j];
  return d;
}

// How far p is off the model: |<p,p> - K| (H3: -1, S3: +1), E3 |w - 1|.
inline double point_error(GeometryKind k, const Vec4& p) {
  if (k == GeometryKind::Euclidean) return std::abs(p.w - 1);
  return std::abs(model::inner(k, p, p) - model::curvature(k));
}

// How far the unit tangent v at p is from unit and tangent: max(|<v,v> - 1|, |<p,v>|).
inline double tangent_error(GeometryKind k, const Vec4& p, const Vec4& v) {
  const double tangency =
      k == GeometryKind::Euclidean ? std::abs(v.w) : std::abs(model::inner(k, p, v));
  return std::max(std::abs(model::inner(k, v, v) - 1), tangency);
}

inline std::string geometry_label(const ::testing::TestParamInfo<GeometryKind>& info) {
  return geometry_name(info.param);
}

class ModelSampler {
 public:
  ModelSampler(GeometryKind k, uint64_t seed) : k_(k), gen_(seed) {}

  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(gen_);
  }
  Vec3 unit3() {
    std::normal_distribution<double> g;
    return normalize(Vec3{g(gen_), g(gen_), g(gen_)});
  }
  // Exponential coordinates of length up to `radius` (uniform in length and direction).
  Vec3 ball(double radius) { return uniform(0, radius) * unit3(); }
  // A point at distance up to `radius` from the origin.
  Vec4 point(double radius) { return model::exp_origin(k_, ball(radius)); }
  // A random unit tangent at p.
  Vec4 tangent(const Vec4& p) {
    std::normal_distribution<double> g;
    return model::normalize_tangent(k_, p, {g(gen_), g(gen_), g(gen_), g(gen_)});
  }
  // A unit tangent at p perpendicular to the unit tangent v.
  Vec4 perpendicular(const Vec4& p, const Vec4& v) {
    const Vec4 u = tangent(p);
    return model::normalize_tangent(k_, p, u - model::inner(k_, u, v) * v);
  }
  Mat4 rotation() { return model::rotation(unit3(), uniform(-3.14, 3.14)); }
  // An isometry moving the origin up to `radius` away, with a random rotation.
  Mat4 isometry(double radius) { return model::translation(k_, ball(radius)) * rotation(); }

 private:
  GeometryKind k_;
  std::mt19937_64 gen_;
};

}  // namespace geodesic::test
