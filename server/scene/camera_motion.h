// Moving a camera in its own frame, in double precision: the daemon's walkthrough.
#pragma once

#include "geometry/model.h"

namespace geodesic {

// A move in the camera's own frame: geodesic lengths along its right, up and forward (-z)
// directions, then a turn by yaw (about up), pitch (about right) and roll (about the view
// axis), in degrees.
struct CameraMotion {
  double forward = 0, right = 0, up = 0;
  double yaw = 0, pitch = 0, roll = 0;
};

// The pose after the motion, re-orthonormalised onto the isometry group. (Carrying it back
// into a fundamental domain is the renderer's placement: see render/prepare/cells.h.)
Mat4 apply_motion(GeometryKind kind, const Mat4& pose, const CameraMotion& motion);

}  // namespace geodesic
