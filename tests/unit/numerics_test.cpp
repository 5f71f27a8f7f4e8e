// Numerics suite, CPU part: how far double-precision points, frames and composed isometries
// drift off the model over long chains, in all three geometries. (The float side, far, tiny
// and huge objects through the device, is tests/render/numerics_probe_test.cpp; the numbers
// are collected in docs/numerics.md.)
//
// A pose is a matrix whose column 3 is a point and columns 0-2 an orthonormal frame there.
// Re-normalising after each step means normalize_point on the point and normalize_tangent
// with Gram-Schmidt on the frame, which is exactly reorthonormalize on the matrix: the point
// first (E3 w := 1, H3 w := sqrt(1 + |x|^2), S3 p / |p|), then each frame vector stripped of
// its components along the earlier ones and projected onto the point's tangent space.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>

#include "geometry/model.h"
#include "model_sampler.h"
#include "test_constants.h"

namespace geodesic::test {
namespace {


// The worst of |<p,p> - K| (E3 |w - 1|) and, for the frame, |<e_i,e_j> - delta_ij| and
// |<p, e_i>| over a pose.
double pose_error(GeometryKind k, const Mat4& g) {
  const auto col = [&](int c) { return Vec4{g.m[0][c], g.m[1][c], g.m[2][c], g.m[3][c]}; };
  double error = point_error(k, col(3));
  for (int i = 0; i < 3; ++i) {
    error = std::max(error, tangent_error(k, col(3), col(i)));
    for (int j = 0; j < i; ++j) error = std::max(error, std::abs(model::inner(k, col(i), col(j))));
  }
  return error;
}

struct Drift {
  double worst_on_model = 0;  // pose_error over every step
  double end_error = 0;       // max |entry| off the reference at the end
};

void print(const char* what, GeometryKind k, const Drift& d) {
  std::printf("  %-44s %-10s worst off-model %9.3g   end error %9.3g\n", what, geometry_name(k),
              d.worst_on_model, d.end_error);
}

class Numerics : public ::testing::TestWithParam<GeometryKind> {
 protected:
  GeometryKind k = GetParam();
  ModelSampler sample{k, 99};

  // A pairing-like step: a transvection of length 1..2, then a rotation about the origin. In
  // H3 it heads back towards the origin once the pose is more than 2 away, as a face pairing
  // returns a ray to the fundamental domain, so the walk stays bounded.
  Mat4 step(const Mat4& pose) {
    const Vec4 p{pose.m[0][3], pose.m[1][3], pose.m[2][3], pose.m[3][3]};
    Vec3 direction = sample.unit3();
    const Vec3 away = model::log_origin(k, p);
    if (k == GeometryKind::Hyperbolic && length(away) > 2) direction = -normalize(away);
    return sample.rotation() * model::translation(k, sample.uniform(1, 2) * direction);
  }
};

// 10^3 random steps applied to a pose, then undone by their inverses in reverse order: the
// pose must come back to the identity. Three ways: raw products; the point and frame
// re-normalised after every step; and (same formulas) the composed matrix re-orthonormalised.
TEST_P(Numerics, ThousandComposedIsometriesStayOnTheModelAndUndo) {
  constexpr int kSteps = 1000;
  std::vector<Mat4> steps;
  Mat4 pose = Mat4::identity();
  for (int i = 0; i < kSteps; ++i) {
    steps.push_back(step(pose));
    pose = model::reorthonormalize(k, steps.back() * pose);
  }
  Drift raw, renormalised;
  Mat4 a = Mat4::identity(), b = Mat4::identity();
  const auto walk = [&](const Mat4& g) {
    a = g * a;
    b = model::reorthonormalize(k, g * b);
    raw.worst_on_model = std::max(raw.worst_on_model, pose_error(k, a));
    renormalised.worst_on_model = std::max(renormalised.worst_on_model, pose_error(k, b));
  };
  for (const Mat4& g : steps) walk(g);
  for (int i = kSteps - 1; i >= 0; --i) walk(model::inverse_isometry(k, steps[i]));
  raw.end_error = max_abs(difference(a, Mat4::identity()));
  renormalised.end_error = max_abs(difference(b, Mat4::identity()));
  print("1e3 isometries + inverses, raw products", k, raw);
  print("1e3 isometries + inverses, re-orthonormalised", k, renormalised);
  // Re-normalised poses stay on the model to round-off of coordinates below ~cosh 4 ~ 30.
  EXPECT_LE(renormalised.worst_on_model, 1e3 * kEps);
  EXPECT_LE(renormalised.end_error, 1e-11);
  EXPECT_LE(raw.end_error, 1e-8);  // measured, not needed: the raw product also returns
}

// A camera flying 10^4 steps of 0.01 forward, turning 0.02 rad about its up axis each step (a
// circle: radius 0.5 in E3, atanh 0.5 in H3, atan 0.5 in S3), re-orthonormalised each step.
// Reference: (T R)^10^4 by 14 squarings, each re-orthonormalised.
TEST_P(Numerics, CameraWalkOfTenThousandStepsStaysOnTheModelAndOnCourse) {
  constexpr int kSteps = 10000;
  const Mat4 move = model::translation(k, {0, 0, -0.01}) * model::rotation({0, 1, 0}, 0.02);
  Drift drift;
  Mat4 pose = Mat4::identity();
  for (int i = 0; i < kSteps; ++i) {
    pose = model::reorthonormalize(k, pose * move);
    drift.worst_on_model = std::max(drift.worst_on_model, pose_error(k, pose));
  }
  Mat4 exact = Mat4::identity(), power = move;
  for (int n = kSteps; n > 0; n /= 2, power = model::reorthonormalize(k, power * power))
    if (n % 2) exact = model::reorthonormalize(k, exact * power);
  drift.end_error = max_abs(difference(pose, exact));
  print("camera walk 1e4 steps (circle)", k, drift);
  EXPECT_LE(drift.worst_on_model, 8 * kEps);
  // 10^4 steps of round-off, each a few eps: a random walk, far below 1e-11.
  EXPECT_LE(drift.end_error, 1e-11);
}

// The same walk with a random wobble of the turning axis (up to 0.05 rad): the camera drifts
// off the circle. Reference: the same steps undone in reverse order.
TEST_P(Numerics, WanderingCameraWalkUndoesToTheIdentity) {
  constexpr int kSteps = 10000;
  std::vector<Mat4> moves;
  Drift drift;
  Mat4 pose = Mat4::identity();
  for (int i = 0; i < kSteps; ++i) {
    const Vec3 up = normalize(Vec3{0, 1, 0} + 0.05 * sample.unit3());
    moves.push_back(model::translation(k, {0, 0, -0.01}) * model::rotation(up, 0.02));
    pose = model::reorthonormalize(k, pose * moves.back());
    drift.worst_on_model = std::max(drift.worst_on_model, pose_error(k, pose));
  }
  const double distance = model::geodesic_distance(k, model::origin(), pose * model::origin());
  for (int i = kSteps - 1; i >= 0; --i)
    pose = model::reorthonormalize(k, pose * model::inverse_isometry(k, moves[i]));
  drift.end_error = max_abs(difference(pose, Mat4::identity()));
  print("wandering camera 1e4 steps + undo", k, drift);
  std::printf("  %-44s %-10s ended %.3g from the origin\n", "", geometry_name(k), distance);
  EXPECT_LE(drift.worst_on_model, 64 * kEps);
  EXPECT_LE(drift.end_error, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(AllGeometries, Numerics,
                         ::testing::Values(GeometryKind::Euclidean, GeometryKind::Hyperbolic,
                                           GeometryKind::Spherical),
                         geometry_label);

}  // namespace
}  // namespace geodesic::test
