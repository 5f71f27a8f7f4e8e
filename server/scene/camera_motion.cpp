#include "scene/camera_motion.h"

#include <numbers>

namespace geodesic {

Mat4 apply_motion(GeometryKind kind, const Mat4& pose, const CameraMotion& m) {
  constexpr double kDegree = std::numbers::pi / 180;
  // Yaw turns -z towards -x (a left turn for a positive angle), pitch raises -z towards +y,
  // roll lowers +x towards -y: the conventions of the scene format's rotation.
  const Mat4 turn = model::rotation({0, 1, 0}, m.yaw * kDegree) *
                    model::rotation({1, 0, 0}, m.pitch * kDegree) *
                    model::rotation({0, 0, -1}, m.roll * kDegree);
  const Mat4 step = model::translation(kind, {m.right, m.up, -m.forward});
  return model::reorthonormalize(kind, pose * step * turn);
}

}  // namespace geodesic
