// The three model geometries in double precision, as 4-vectors: the reference twin of
// shaders/geometry/{euclidean,hyperbolic,spherical}.glsl (each function is the GLSL routine
// of the same name in camelCase, formula for formula).
//
//   Euclidean E3   points (x, y, z, 1), tangent vectors (x, y, z, 0), form x.x' + y.y' + z.z'
//   Hyperbolic H3  hyperboloid <p,p> = -1, w > 0, Lorentzian form xx' + yy' + zz' - ww'
//   Spherical S3   unit sphere in R4, Euclidean form xx' + yy' + zz' + ww'
//
// The origin is (0, 0, 0, 1) in all three; its tangent space is the xyz subspace, so a unit
// vector (u, 0) is a direction at the origin. Charts: chart(p) = p.xyz / p.w (identity in E3,
// Klein in H3, gnomonic in S3 for w > 0) map geodesics to straight lines, so geodesic planes
// are flat and geodesic triangles are exact triangles there.
#pragma once

#include <optional>

#include "geometry/vec.h"

namespace geodesic {

enum class GeometryKind { Euclidean, Hyperbolic, Spherical };

const char* geometry_name(GeometryKind kind);  // "euclidean", "hyperbolic", "spherical"

// Vec4 arithmetic, componentwise, for points and tangents of the models.
constexpr Vec4 operator+(const Vec4& a, const Vec4& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w};
}
constexpr Vec4 operator-(const Vec4& a, const Vec4& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w};
}
constexpr Vec4 operator-(const Vec4& a) { return {-a.x, -a.y, -a.z, -a.w}; }
constexpr Vec4 operator*(double s, const Vec4& a) { return {s * a.x, s * a.y, s * a.z, s * a.w}; }
constexpr Vec4 operator/(const Vec4& a, double s) { return {a.x / s, a.y / s, a.z / s, a.w / s}; }
constexpr double dot(const Vec4& a, const Vec4& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}

namespace model {

constexpr Vec4 origin() { return {0, 0, 0, 1}; }

// Sectional curvature: 0, -1, +1. The form is x.x' + y.y' + z.z' + K w w' (E3: w ignored).
double curvature(GeometryKind k);

// The model's bilinear form <a, b> (E3: on the xyz part only).
double inner(GeometryKind k, const Vec4& a, const Vec4& b);

// Point and unit tangent at arc length t along the geodesic leaving p with unit tangent v:
// E3 p + t v; H3 cosh t p + sinh t v; S3 cos t p + sin t v.
Vec4 geodesic_point(GeometryKind k, const Vec4& p, const Vec4& v, double t);
Vec4 geodesic_tangent(GeometryKind k, const Vec4& p, const Vec4& v, double t);

// A(d): the geodesic sphere of radius d has area 4 pi A(d), and a point source's irradiance
// falls off as 1 / A(d): d^2 in E3, sinh^2 d in H3, sin^2 d in S3.
double sphere_area_factor(GeometryKind k, double d);
// sphere_area_factor(geodesic_distance(a, b)) computed without the distance: |b-a|^2 in E3,
// q (1 + q/4) with q = 4 sinh^2(d/2) in H3, |b-a|^2 |b+a|^2 / 4 in S3.
double area_factor_between(GeometryKind k, const Vec4& a, const Vec4& b);

// Geodesic distance (S3: the shorter arc, in [0, pi]).
double geodesic_distance(GeometryKind k, const Vec4& a, const Vec4& b);

// Unit tangent at `from` of the shortest geodesic to `to` (zero vector when undefined:
// to == from, or to the antipode in S3).
Vec4 geodesic_direction(GeometryKind k, const Vec4& from, const Vec4& to);

// Exponential coordinates at the origin: the end of the geodesic from the origin along w/|w|
// of length |w|; and its inverse (S3: for points other than the antipode of the origin).
Vec4 exp_origin(GeometryKind k, const Vec3& w);
Vec3 log_origin(GeometryKind k, const Vec4& p);

// The transvection (pure translation / boost) carrying the origin to q along the geodesic
// between them, and its inverse. Columns 0-2 are the parallel-transported origin frame.
Mat4 translation_to(GeometryKind k, const Vec4& q);
Mat4 translation_from(GeometryKind k, const Vec4& q);
// Translation by exponential coordinates w (= translation_to(exp_origin(w))).
Mat4 translation(GeometryKind k, const Vec3& w);
// Rotation about the origin by `angle` radians around `axis` (right-handed); the same matrix
// in all three models.
Mat4 rotation(const Vec3& axis, double angle);
// Inverse of an isometry: E3 affine inverse, H3 J g^T J, S3 g^T.
Mat4 inverse_isometry(GeometryKind k, const Mat4& g);

// A geodesic plane given in the chart as {X : N . X = delta} (N unit): the reflection in it,
// and the unit normal (pointing along +N) in the tangent space at a point q on it.
Mat4 reflection_in_chart_plane(GeometryKind k, const Vec3& normal, double delta);
// That reflection applied to a point or tangent x: twin of reflectInChartPlane, which mirrored
// quotients use instead of their pairing matrices.
Vec4 reflect_in_chart_plane(GeometryKind k, const Vec4& x, const Vec3& normal, double delta);
Vec4 chart_plane_normal(GeometryKind k, const Vec4& q, const Vec3& normal, double delta);

// Outward unit normal at q of the geodesic sphere centred at c.
Vec4 sphere_normal(GeometryKind k, const Vec4& c, const Vec4& q);

// Projection back onto the model (H3: w > 0 sheet; E3: w = 1), and of a vector onto the unit
// tangent space at p. Used after every isometry applied in floating point.
Vec4 normalize_point(GeometryKind k, const Vec4& p);
Vec4 normalize_tangent(GeometryKind k, const Vec4& p, const Vec4& v);
// The isometry nearest g by Gram–Schmidt in the model's form, origin image (column 3) first;
// in H3 in binary128, so that a pose 20 out keeps its frame (geometry/wide_isometry.h).
Mat4 reorthonormalize(GeometryKind k, const Mat4& g);
// Largest entry of |g^T G g - G| (G the form; E3: of the linear part, plus |bottom row - e_w|).
double isometry_error(GeometryKind k, const Mat4& g);
// isometry_error over the square of g's largest entry (when above 1): what round-off leaves
// of an isometry written in double is ~1e-16 of it however far it carries the origin, while
// isometry_error grows as e^(2D) in H3 (a pose 20 out: ~10).
double relative_isometry_error(GeometryKind k, const Mat4& g);
// S3: whether g is the antipodal map -1 (to 1e-9 in every entry).
bool is_antipodal_map(const Mat4& g);

// Chart (p.xyz / p.w) and its inverse onto the model's w > 0 part.
Vec3 chart(GeometryKind k, const Vec4& p);
Vec4 lift(GeometryKind k, const Vec3& x);
// Chart image of the geodesic (p, v): chart(p) + s * chart_direction(p, v), where
// s = chart_parameter(t) is a monotonic reparametrisation of arc length t (while p.w stays
// positive), and distance_from_chart_parameter its inverse.
Vec3 chart_direction(GeometryKind k, const Vec4& p, const Vec4& v);
double chart_parameter(GeometryKind k, const Vec4& p, const Vec4& v, double t);
double distance_from_chart_parameter(GeometryKind k, const Vec4& p, const Vec4& v, double s);

// Both arc lengths where the geodesic (p, v) meets the sphere of centre c and radius r, as
// intersect_sphere computes them. disc is r^2, sinh^2 r or sin^2 r less the same function of
// the distance from c to the geodesic: disc < 0 means a miss (t0, t1 are then meaningless).
// S3: the hits repeat with period 2 pi; t0 <= t1 always.
struct SphereRoots {
  double disc = 0;
  double t0 = 0;
  double t1 = 0;
};
SphereRoots sphere_roots(GeometryKind k, const Vec4& p, const Vec4& v, const Vec4& c, double r);

// Smallest arc length t in (t_min, t_max) where the geodesic (p, v) meets the geodesic sphere
// of centre c and radius r.
std::optional<double> intersect_sphere(GeometryKind k, const Vec4& p, const Vec4& v,
                                       const Vec4& c, double r, double t_min, double t_max);

// The arc length a secondary ray's origin steps off the surface it leaves: 1e-4 plus 2^-15
// (256 float ulps) of the largest coordinate of q that carries rounding error (E3: xyz;
// H3, S3: all four), so float round-off never lets the ray hit that surface again.
double surface_offset_length(GeometryKind k, const Vec4& q);
// That step along the geodesic leaving q with unit tangent n, projected back onto the model.
Vec4 offset_from_surface(GeometryKind k, const Vec4& q, const Vec4& n);

// A chart line o + s d against the triangle abc given in the chart (geodesic triangles are
// flat there in every geometry): what the acceleration structure reports, with Vulkan's
// barycentrics (position = (1-u-v) a + u b + v c). Closed, two-sided, s in (s_min, s_max].
// Woop, Benthin and Wald's watertight test (JCGT 2013), as its float twin
// (shaders/geometry/triangle.glsl) is: in float, a line through an edge or a vertex that two
// triangles share meets at least one of them.
struct ChartTriangleHit {
  double s = 0;
  double u = 0;
  double v = 0;
};
std::optional<ChartTriangleHit> intersect_chart_triangle(const Vec3& o, const Vec3& d,
                                                         const Vec3& a, const Vec3& b,
                                                         const Vec3& c, double s_min,
                                                         double s_max);

// Parallel transport of tangent u at p along the geodesic (p, v) by arc length t.
Vec4 parallel_transport(GeometryKind k, const Vec4& p, const Vec4& v, double t, const Vec4& u);

}  // namespace model
}  // namespace geodesic
