// A horosphere of H3 (scene type "horosphere"): the limit of spheres whose centres run off to
// an ideal point, the boundary of a horoball, the shape of a cusp's cross-section. In the
// hyperboloid model it is {x : <x, l> = -1} for a light-like, future-pointing l aimed at its
// ideal point, and its horoball is {<x, l> > -1}; l = e^d (n, 1) puts it at signed distance d
// from the origin along the unit n (the origin is inside when d < 0). In the Klein chart it is
// an ellipsoid touching the sphere at infinity at n. GLSL twin: shaders/primitives/shapes/
// horosphere.glsl.
//
// Scene fields: "direction" (vec3, towards its ideal point, any nonzero length) and
// "distance" (signed, from the origin to the horosphere along it, |d| <= 30: l's entries
// e^|d| stay well inside float's range in the shaders). ShapeParams: a = l.
//
// Intersection: along x(t) = p cosh t + v sinh t, <x(t), l> = (A e^t + C e^-t) / 2 with
// A = <p + v, l> and C = <p - v, l>, both <= 0 (p + v and p - v are light-like and future-
// pointing, like l): with u = e^t, A u^2 + 2 u + C = 0, whose roots C / q (entering) and q / A
// (leaving; none when A = 0, the ray running into the ideal point) for q = -(1 + sqrt(1 - AC))
// suffer no cancellation; nor do A and C (see intersect). Normal: at q on it the tangent q - l, already of unit length
// (<q - l, q - l> = -2 <q, l> - 1 = 1), pointing out of the horoball.
#include <algorithm>
#include <cmath>
#include <limits>

#include "common/shape_kinds.h"
#include "scene/shape.h"

namespace geodesic {
namespace {

constexpr double kMaxDistance = 30;

ShapeParams read(const JsonNode& object, GeometryKind k) {
  if (k != GeometryKind::Hyperbolic)
    object.at("type").fail("a horosphere exists only in hyperbolic space");
  const JsonNode direction = object.at("direction");
  const Vec3 n = read_vec3(direction);
  if (!(length(n) > 0)) direction.fail("must not be zero");
  const JsonNode distance = object.at("distance");
  const double d = read_number(distance);
  if (std::abs(d) > kMaxDistance) distance.fail("must be within [-30, 30]");
  ShapeParams params;
  params.a = std::exp(d) * Vec4(normalize(n), 1);
  return params;
}

// The solid ellipsoid of the horoball, l = lambda (n, 1): its axis runs from tanh d to 1 along
// n (lambda = e^d), centre lambda^2 / (1 + lambda^2) n, half-axes 1 / (1 + lambda^2) along n
// and 1 / sqrt(1 + lambda^2) across.
std::optional<ChartBox> chart_box(GeometryKind, const ShapeParams& in_frame) {
  const double lambda = in_frame.a.w, lambda2 = lambda * lambda;
  const Vec3 n = in_frame.a.xyz() / lambda;
  const Vec3 centre = lambda2 / (1 + lambda2) * n;
  const double along = 1 / (1 + lambda2), across2 = 1 / (1 + lambda2);
  const Vec3 half{std::sqrt(along * along * n.x * n.x + across2 * (1 - n.x * n.x)),
                  std::sqrt(along * along * n.y * n.y + across2 * (1 - n.y * n.y)),
                  std::sqrt(along * along * n.z * n.z + across2 * (1 - n.z * n.z))};
  return ChartBox{centre - half, centre + half};
}

double intersect(GeometryKind k, const ShapeParams& s, const Vec4& p, const Vec4& v, double t_min,
                 double t_max) {
  // l = alpha p + beta v + m, m orthogonal to both: A = beta - alpha, C = -alpha - beta and
  // AC = <m, m>; the one of A, C that does not cancel directly, the other from <m, m>.
  const double alpha = -model::inner(k, p, s.a), beta = model::inner(k, v, s.a);
  const Vec4 m = s.a - alpha * p - beta * v;
  const double mm = std::max(model::inner(k, m, m), 0.0);
  const double a = beta <= 0 ? beta - alpha : mm / (-alpha - beta);
  const double c = beta <= 0 ? mm / a : -alpha - beta;
  const double discriminant = 1 - mm;
  if (discriminant < 0) return std::numeric_limits<double>::infinity();
  const double q = -(1 + std::sqrt(discriminant));
  const double roots[2] = {c < 0 ? std::log(c / q) : -std::numeric_limits<double>::infinity(),
                           a < 0 ? std::log(q / a) : std::numeric_limits<double>::infinity()};
  for (const double t : roots)
    if (t > t_min && t < t_max) return t;
  return std::numeric_limits<double>::infinity();
}

Vec4 normal(GeometryKind k, const ShapeParams& s, const Vec4& q) {
  return model::normalize_tangent(k, q, q - s.a);
}

}  // namespace

extern const ShapeKind kHorosphere{
    "horosphere", SHAPE_HOROSPHERE, {"type", "material", "direction", "distance"},
    read,         chart_box,        intersect,
    normal};

}  // namespace geodesic
