// Euclidean E3 in double precision: the reference twin of shaders/geometry/euclidean.glsl and
// shaders/primitives/sphere.glsl. Each function is the GLSL routine of the same name
// (camelCase there), formula for formula, so tests can hold the float shaders against it.
#pragma once

#include <optional>

#include "geometry/vec.h"

namespace geodesic::euclidean {

struct Ray {
  Vec3 origin;
  Vec3 direction;  // unit
};

inline Vec3 geodesic_point(const Ray& ray, double t) { return ray.origin + t * ray.direction; }

inline double geodesic_distance(const Vec3& a, const Vec3& b) { return length(b - a); }

// Unit tangent at `from` of the geodesic towards `to`.
inline Vec3 geodesic_direction(const Vec3& from, const Vec3& to) { return normalize(to - from); }

// The metric g_p(u, v) at p; flat space ignores p.
inline double metric_dot(const Vec3& /*p*/, const Vec3& u, const Vec3& v) { return dot(u, v); }

// Mirror reflection of direction d about the unit normal n (with the metric at p).
inline Vec3 reflect_direction(const Vec3& p, const Vec3& d, const Vec3& n) {
  return d - 2.0 * metric_dot(p, d, n) * n;
}

// Camera ray through a direction given in the camera frame, moved by the camera isometry.
inline Ray camera_ray(const Mat4& pose, const Vec3& direction_in_camera) {
  return {(pose * Vec4(0, 0, 0, 1)).xyz(), normalize((pose * Vec4(direction_in_camera, 0)).xyz())};
}

// A spawn point off the surface along its normal, scaled with the magnitude of p so that
// float round-off in the shader never lets a secondary ray hit the surface it leaves.
Vec3 offset_from_surface(const Vec3& p, const Vec3& n);

// Both roots of |origin + t*dir - center| = radius (dir unit), computed as intersectSphere
// does: the discriminant comes from the closest-approach vector, so it stays accurate for far
// or grazing rays. disc < 0 means the line misses (t0, t1 are then meaningless).
struct SphereRoots {
  double disc = 0;  // radius^2 - (squared distance from the centre to the line)
  double t0 = 0;    // t0 <= t1
  double t1 = 0;
};
SphereRoots sphere_roots(const Vec3& origin, const Vec3& dir, const Vec3& center, double radius);

// Nearest t in (t_min, t_max) where the ray meets the sphere.
std::optional<double> intersect_sphere(const Vec3& origin, const Vec3& dir, const Vec3& center,
                                       double radius, double t_min, double t_max);

// A ray-triangle hit with Vulkan's barycentrics: position = (1-u-v)*a + u*b + v*c.
struct TriangleHit {
  double t = 0;
  double u = 0;
  double v = 0;
};

// Nearest hit in (t_min, t_max) with the closed, two-sided triangle abc (Moeller-Trumbore);
// the reference for what the acceleration structure reports to triangle hit shaders.
std::optional<TriangleHit> intersect_triangle(const Ray& ray, const Vec3& a, const Vec3& b,
                                              const Vec3& c, double t_min, double t_max);

}  // namespace geodesic::euclidean
