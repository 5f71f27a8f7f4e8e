// Two facts of S3 that the default scene of a spherical space (default_scene.h) has to allow
// for. Its group is finite, and every image of a point light shines on every point, along both
// ways round: in the catalogue's scenes the light's images together bring 2-17 times what
// the nearest brings to a sphere's centre, more the larger the group. And every geodesic from
// the camera passes through the camera's antipode: an object there fills the whole background
// (in L(5,2), an edge of the domain does).
#pragma once

#include <vector>

#include "geometry/model.h"
#include "scene/manifold.h"

namespace geodesic {

// The elements of the group the domain's face pairings generate (S3: finite), the identity
// first; the identity alone for a domain without faces or for a group too large to list.
std::vector<Mat4> spherical_group(const Manifold& manifold);

// The irradiance that a point light of unit intensity at `light` and all its images under
// `group` bring to p, facing each: 1 / sin^2 of the distance, along both ways round, except
// where -1 is in the group (then one image's long way is another's short way).
double orbit_irradiance(const std::vector<Mat4>& group, const Vec4& light, const Vec4& p);

struct BallObstacle {
  Vec4 centre;
  double radius;
};

// How far the antipode of `eye`, and each of its images, stays from the domain's edges (the
// chart segments of `domain`, each widened by `edge_radius`) and from the balls: the least
// distance from any of those points to any of those surfaces (0 when one lies inside).
double antipode_clearance(const std::vector<Mat4>& group, const Polyhedron& domain,
                          double edge_radius, const std::vector<BallObstacle>& balls,
                          const Vec4& eye);

}  // namespace geodesic
