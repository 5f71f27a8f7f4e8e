// Walking the camera in its own frame, in every geometry.
#include <gtest/gtest.h>

#include "scene/camera_motion.h"

namespace geodesic {
namespace {

class CameraMotionTest : public ::testing::TestWithParam<GeometryKind> {};

TEST_P(CameraMotionTest, ForwardGoesAlongMinusZByTheGeodesicLength) {
  const GeometryKind k = GetParam();
  const Mat4 pose = apply_motion(k, Mat4::identity(), {.forward = 0.7});
  const Vec4 p = pose * model::origin();
  EXPECT_NEAR(model::geodesic_distance(k, model::origin(), p), 0.7, 1e-12);
  const Vec3 log = model::log_origin(k, p);
  EXPECT_NEAR(log.z, -0.7, 1e-12);
  EXPECT_NEAR(log.x, 0, 1e-12);
}

TEST_P(CameraMotionTest, YawLeftThenForwardGoesAlongMinusX) {
  const GeometryKind k = GetParam();
  Mat4 pose = apply_motion(k, Mat4::identity(), {.yaw = 90});
  pose = apply_motion(k, pose, {.forward = 0.5});
  const Vec3 log = model::log_origin(k, pose * model::origin());
  EXPECT_NEAR(log.x, -0.5, 1e-12);
  EXPECT_NEAR(log.z, 0, 1e-12);
}

TEST_P(CameraMotionTest, ALongWalkStaysAnIsometryAndComesBack) {
  const GeometryKind k = GetParam();
  Mat4 pose = Mat4::identity();
  // Turning 1.8 degrees every 0.01 (curvature pi, above H3's 1, so the path is a circle in
  // every geometry): 10^4 steps are 50 laps.
  for (int i = 0; i < 10000; ++i) pose = apply_motion(k, pose, {.forward = 0.01, .yaw = 1.8});
  EXPECT_LT(model::isometry_error(k, pose), 1e-12);
  const double away = model::geodesic_distance(k, model::origin(), pose * model::origin());
  EXPECT_LT(away, 1.0);
  if (k == GeometryKind::Euclidean) EXPECT_NEAR(away, 0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(AllGeometries, CameraMotionTest,
                         ::testing::Values(GeometryKind::Euclidean, GeometryKind::Hyperbolic,
                                           GeometryKind::Spherical),
                         [](const auto& info) { return std::string(geometry_name(info.param)); });

}  // namespace
}  // namespace geodesic
