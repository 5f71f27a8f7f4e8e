#include "geometry/euclidean.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace geodesic::euclidean {

Vec3 offset_from_surface(const Vec3& p, const Vec3& n) {
  const double scale = 1e-4 + 0x1p-15 * std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return p + scale * n;
}

SphereRoots sphere_roots(const Vec3& origin, const Vec3& dir, const Vec3& center, double radius) {
  const Vec3 f = origin - center;
  const double b = -dot(f, dir);
  const Vec3 l = f + b * dir;  // from the centre to the line's closest point
  SphereRoots roots;
  roots.disc = radius * radius - dot(l, l);
  if (roots.disc < 0.0) return roots;
  // sqrt(disc) takes the sign of b so the sum never cancels; the other root is c / q since
  // t0 * t1 = c.
  const double q = b + (b >= 0.0 ? 1.0 : -1.0) * std::sqrt(roots.disc);
  const double c = dot(f, f) - radius * radius;
  roots.t0 = q != 0.0 ? c / q : 0.0;
  roots.t1 = q;
  if (roots.t0 > roots.t1) std::swap(roots.t0, roots.t1);
  return roots;
}

std::optional<double> intersect_sphere(const Vec3& origin, const Vec3& dir, const Vec3& center,
                                       double radius, double t_min, double t_max) {
  const SphereRoots roots = sphere_roots(origin, dir, center, radius);
  if (roots.disc < 0.0) return std::nullopt;
  if (roots.t0 > t_min && roots.t0 < t_max) return roots.t0;
  if (roots.t1 > t_min && roots.t1 < t_max) return roots.t1;
  return std::nullopt;
}

std::optional<TriangleHit> intersect_triangle(const Ray& ray, const Vec3& a, const Vec3& b,
                                              const Vec3& c, double t_min, double t_max) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = cross(ray.direction, e2);
  const double det = dot(e1, p);
  if (det == 0.0) return std::nullopt;  // ray parallel to the plane, or degenerate triangle
  const double inv = 1.0 / det;
  const Vec3 s = ray.origin - a;
  const double u = dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const Vec3 q = cross(s, e1);
  const double v = dot(ray.direction, q) * inv;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = dot(e2, q) * inv;
  if (t <= t_min || t >= t_max) return std::nullopt;
  return TriangleHit{t, u, v};
}

}  // namespace geodesic::euclidean
