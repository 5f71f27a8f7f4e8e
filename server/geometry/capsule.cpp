#include "geometry/capsule.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geodesic {
namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

// The roots of A s^2 + 2 B s + C = 0 in increasing order (A > 0), computed without the
// cancellation of the textbook formula; false when there are none.
bool roots(double A, double B, double C, double& s0, double& s1) {
  const double h = B * B - A * C;
  if (h < 0) return false;
  const double q = -(B + std::copysign(std::sqrt(h), B));
  if (q == 0) {
    s0 = s1 = 0;
    return true;
  }
  s0 = q / A;
  s1 = C / q;
  if (s0 > s1) std::swap(s0, s1);
  return true;
}

Vec3 nearest_on_axis(const Capsule& c, const Vec3& x) {
  const Vec3 axis = c.b - c.a;
  const double y = std::clamp(dot(x - c.a, axis) / dot(axis, axis), 0.0, 1.0);
  return c.a + y * axis;
}

}  // namespace

double intersect_capsule(const Capsule& c, const Vec3& o, const Vec3& d, double s_min,
                         double s_max) {
  const Vec3 axis = c.b - c.a;
  const double length2 = dot(axis, axis);
  const Vec3 oa = o - c.a;
  // The infinite cylinder: |perp(oa + s d)|^2 = r^2, perp removing the part along the axis.
  // Both caps lie inside it, so a line that misses it misses the capsule: the first test, as
  // most lines tested miss (the shader returns there, before anything else).
  const Vec3 oPerp = oa - (dot(oa, axis) / length2) * axis;
  const Vec3 dPerp = d - (dot(d, axis) / length2) * axis;
  const double A = dot(dPerp, dPerp), B = dot(oPerp, dPerp),
               C = dot(oPerp, oPerp) - c.radius * c.radius;
  if (B * B - A * C < 0 && C > 0) return kNone;
  double best = kNone;
  auto consider = [&](double s, bool valid) {
    if (valid && s > s_min && s <= s_max && s < best) best = s;
  };
  double s0, s1;
  if (A > 0 && roots(A, B, C, s0, s1)) {
    for (double s : {s0, s1}) {
      const double y = dot(oa + s * d, axis);
      consider(s, y >= 0 && y <= length2);
    }
  } else if (C > 0) {
    return kNone;  // parallel to the axis and outside the cylinder
  }
  // The caps: the sphere of radius r about each end, where the point lies beyond that end.
  const double dd = dot(d, d);
  for (int end = 0; end < 2; ++end) {
    const Vec3 oc = o - (end == 0 ? c.a : c.b);
    if (!roots(dd, dot(oc, d), dot(oc, oc) - c.radius * c.radius, s0, s1)) continue;
    for (double s : {s0, s1}) {
      const double y = dot(oa + s * d, axis);
      consider(s, end == 0 ? y < 0 : y > length2);
    }
  }
  return best;
}

Vec3 capsule_normal(const Capsule& c, const Vec3& x) { return normalize(x - nearest_on_axis(c, x)); }

double distance_to_axis(const Capsule& c, const Vec3& x) { return length(x - nearest_on_axis(c, x)); }

}  // namespace geodesic
