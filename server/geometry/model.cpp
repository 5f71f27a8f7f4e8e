#include "geometry/model.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <utility>

#include "geometry/wide_isometry.h"

namespace geodesic::model {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// (C(t), S(t)): the coefficients of p and v in geodesic_point.
std::pair<double, double> trig(GeometryKind k, double t) {
  switch (k) {
    case GeometryKind::Hyperbolic: return {std::cosh(t), std::sinh(t)};
    case GeometryKind::Spherical: return {std::cos(t), std::sin(t)};
    default: return {1.0, t};
  }
}

// The part of v tangent at p (p on the model): v - K <p, v> p; E3 drops w.
Vec4 tangent_part(GeometryKind k, const Vec4& p, const Vec4& v) {
  if (k == GeometryKind::Euclidean) return {v.xyz(), 0};
  return v - curvature(k) * inner(k, p, v) * p;
}

Vec4 column(const Mat4& g, int c) { return {g.m[0][c], g.m[1][c], g.m[2][c], g.m[3][c]}; }

// The smallest of t + 2 pi n (n integer) above t_min.
double next_turn_after(double t, double t_min) {
  double shifted = t + kTwoPi * std::ceil((t_min - t) / kTwoPi);
  if (shifted <= t_min) shifted += kTwoPi;
  return shifted;
}

}  // namespace

double curvature(GeometryKind k) {
  switch (k) {
    case GeometryKind::Hyperbolic: return -1;
    case GeometryKind::Spherical: return 1;
    default: return 0;
  }
}

double inner(GeometryKind k, const Vec4& a, const Vec4& b) {
  return dot(a.xyz(), b.xyz()) + curvature(k) * a.w * b.w;
}

Vec4 geodesic_point(GeometryKind k, const Vec4& p, const Vec4& v, double t) {
  const auto [c, s] = trig(k, t);
  return c * p + s * v;
}

Vec4 geodesic_tangent(GeometryKind k, const Vec4& p, const Vec4& v, double t) {
  const auto [c, s] = trig(k, t);
  return -curvature(k) * s * p + c * v;
}

double sphere_area_factor(GeometryKind k, double d) {
  const double s = trig(k, d).second;
  return s * s;
}

namespace {
// H3: 4 sinh^2(d/2) for d = d(a, b). <b-a, b-a> keeps close points exact but cancels for far
// ones, where 2 (cosh d - 1) from -<a, b> = cosh d is the accurate one.
double chord_squared(const Vec4& a, const Vec4& b) {
  const GeometryKind k = GeometryKind::Hyperbolic;
  const double cosh_d = -inner(k, a, b);
  const Vec4 d = b - a;
  return cosh_d > 2 ? 2 * (cosh_d - 1) : std::max(0.0, inner(k, d, d));
}
}  // namespace

double area_factor_between(GeometryKind k, const Vec4& a, const Vec4& b) {
  const Vec4 d = b - a;
  switch (k) {
    case GeometryKind::Hyperbolic: {
      const double q = chord_squared(a, b);
      return q * (1 + 0.25 * q);
    }
    case GeometryKind::Spherical: return 0.25 * dot(d, d) * dot(a + b, a + b);
    default: return dot(d.xyz(), d.xyz());
  }
}

double geodesic_distance(GeometryKind k, const Vec4& a, const Vec4& b) {
  const Vec4 d = b - a;
  switch (k) {
    case GeometryKind::Hyperbolic: return 2 * std::asinh(0.5 * std::sqrt(chord_squared(a, b)));
    case GeometryKind::Spherical:  // |b-a| = 2 sin(d/2), |b+a| = 2 cos(d/2): exact for all d
      return 2 * std::atan2(std::sqrt(dot(d, d)), std::sqrt(dot(a + b, a + b)));
    default: return length(d.xyz());
  }
}

Vec4 geodesic_direction(GeometryKind k, const Vec4& from, const Vec4& to) {
  const Vec4 u = tangent_part(k, from, to - from);  // |u| = sin d in S3
  // Near the antipode u is round-off: every direction leads there.
  constexpr double kAntipode = 64 * DBL_EPSILON;
  if (k == GeometryKind::Spherical && dot(from, to) < 0 && dot(u, u) <= kAntipode * kAntipode)
    return {};
  return normalize_tangent(k, from, u);
}

Vec4 exp_origin(GeometryKind k, const Vec3& w) {
  const double t = length(w);
  if (t == 0) return origin();
  return geodesic_point(k, origin(), Vec4(w / t, 0), t);
}

Vec3 log_origin(GeometryKind k, const Vec4& p) {
  const Vec3 x = p.xyz();
  const double s = length(x);  // sinh t, sin t, t
  if (s == 0 || k == GeometryKind::Euclidean) return x;
  const double t = k == GeometryKind::Hyperbolic ? std::asinh(s) : std::atan2(s, p.w);
  return (t / s) * x;
}

Mat4 translation_to(GeometryKind k, const Vec4& q) {
  const Vec3 x = q.xyz();
  const double kk = curvature(k);
  // [I - K x x^T / (1 + w), x; -K x^T, w] (E3: w = 1). On S3 x x^T / (1 + w) equals
  // (1 - w) x^ x^T: the first form cancels near the antipode (w -> -1), the second near the
  // origin. At the antipode itself no rotation is singled out; x^ = e_x gives the half-turn in
  // the xw plane.
  Vec3 axis = x;
  double scale = 1 / (1 + q.w);
  if (k == GeometryKind::Spherical && q.w < 0) {
    const double s = length(x);
    axis = s > 0 ? x / s : Vec3{1, 0, 0};
    scale = 1 - q.w;
  }
  Mat4 g = Mat4::identity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) g.m[i][j] -= kk * scale * axis[i] * axis[j];
    g.m[i][3] = x[i];
    g.m[3][i] = -kk * x[i];
  }
  g.m[3][3] = k == GeometryKind::Euclidean ? 1 : q.w;
  return g;
}

Mat4 translation_from(GeometryKind k, const Vec4& q) { return translation_to(k, {-q.xyz(), q.w}); }

Mat4 translation(GeometryKind k, const Vec3& w) {
  const double t = length(w);
  if (t == 0) return Mat4::identity();
  const Vec3 u = w / t;
  const auto [c, s] = trig(k, t);
  const double half = trig(k, t / 2).second;
  const double c_minus_1 = -2 * curvature(k) * half * half;  // without cancellation
  Mat4 g = Mat4::identity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) g.m[i][j] += c_minus_1 * u[i] * u[j];
    g.m[i][3] = s * u[i];
    g.m[3][i] = -curvature(k) * s * u[i];
  }
  g.m[3][3] = c;
  return g;
}

Mat4 rotation(const Vec3& axis, double angle) {
  const Vec3 a = normalize(axis);
  const double c = std::cos(angle), s = std::sin(angle);
  const double cross_matrix[3][3] = {{0, -a.z, a.y}, {a.z, 0, -a.x}, {-a.y, a.x, 0}};
  Mat4 g = Mat4::identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      g.m[i][j] = (i == j ? c : 0) + (1 - c) * a[i] * a[j] + s * cross_matrix[i][j];
  return g;
}

Mat4 inverse_isometry(GeometryKind k, const Mat4& g) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = g.m[j][i];
  if (k == GeometryKind::Hyperbolic) {  // J g^T J
    for (int i = 0; i < 3; ++i) r.m[i][3] = -r.m[i][3], r.m[3][i] = -r.m[3][i];
  } else if (k == GeometryKind::Euclidean) {  // [R^T, -R^T x; 0, 1]
    for (int i = 0; i < 3; ++i) {
      r.m[i][3] = -(r.m[i][0] * g.m[0][3] + r.m[i][1] * g.m[1][3] + r.m[i][2] * g.m[2][3]);
      r.m[3][i] = 0;
    }
  }
  return r;
}

Vec4 reflect_in_chart_plane(GeometryKind k, const Vec4& x, const Vec3& normal, double delta) {
  return reflection_in_chart_plane(k, normal, delta) * x;
}

Mat4 reflection_in_chart_plane(GeometryKind k, const Vec3& normal, double delta) {
  Mat4 r = Mat4::identity();
  if (k == GeometryKind::Euclidean) {  // x -> x - 2 (N.x - delta) N
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) r.m[i][j] -= 2 * normal[i] * normal[j];
      r.m[i][3] = 2 * delta * normal[i];
    }
    return r;
  }
  // The plane is m-perpendicular for m = (N, -K delta), unit in the form: p -> p - 2 <p,m> m.
  const double kk = curvature(k);
  const Vec4 m = Vec4(normal, -kk * delta) / std::sqrt(1 + kk * delta * delta);
  const double mi[4] = {m.x, m.y, m.z, m.w}, form[4] = {1, 1, 1, kk};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] -= 2 * mi[i] * mi[j] * form[j];
  return r;
}

Vec4 chart_plane_normal(GeometryKind k, const Vec4& q, const Vec3& normal, double delta) {
  return normalize_tangent(k, q, Vec4(normal, -curvature(k) * delta));
}

Vec4 sphere_normal(GeometryKind k, const Vec4& c, const Vec4& q) {
  return -geodesic_direction(k, q, c);
}

Vec4 normalize_point(GeometryKind k, const Vec4& p) {
  switch (k) {
    // w from xyz: -<p,p> = w^2 - |x|^2 cancels far out, so scaling by it would not do.
    case GeometryKind::Hyperbolic: return {p.xyz(), std::sqrt(1 + dot(p.xyz(), p.xyz()))};
    case GeometryKind::Spherical: return p / std::sqrt(dot(p, p));
    default: return {p.xyz(), 1};
  }
}

Vec4 normalize_tangent(GeometryKind k, const Vec4& p, const Vec4& v) {
  const Vec4 u = tangent_part(k, p, v);
  const double n2 = inner(k, u, u);
  return n2 > 0 ? u / std::sqrt(n2) : Vec4{};
}

Mat4 reorthonormalize(GeometryKind k, const Mat4& g) { return WideIsometry(k, g).matrix(); }

double isometry_error(GeometryKind k, const Mat4& g) {
  const bool affine = k == GeometryKind::Euclidean;
  const int n = affine ? 3 : 4;  // E3: the linear part only
  double error = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double form_ij = inner(k, column(g, i), column(g, j));
      const double expected = i != j ? 0.0 : (i < 3 ? 1.0 : curvature(k));
      error = std::max(error, std::abs(form_ij - expected));
    }
  if (affine)
    for (int j = 0; j < 4; ++j) error = std::max(error, std::abs(g.m[3][j] - (j == 3 ? 1 : 0)));
  return error;
}

double relative_isometry_error(GeometryKind k, const Mat4& g) {
  const double size = std::max(1.0, g.max_abs());
  return isometry_error(k, g) / (size * size);
}

bool is_antipodal_map(const Mat4& g) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if (std::abs(g.m[r][c] + (r == c ? 1.0 : 0.0)) > 1e-9) return false;
  return true;
}

Vec3 chart(GeometryKind /*k*/, const Vec4& p) { return p.xyz() / p.w; }

Vec4 lift(GeometryKind k, const Vec3& x) {
  return Vec4(x, 1) / std::sqrt(1 + curvature(k) * dot(x, x));
}

Vec3 chart_direction(GeometryKind /*k*/, const Vec4& p, const Vec4& v) {
  return (v.xyz() * p.w - p.xyz() * v.w) / (p.w * p.w);
}

double chart_parameter(GeometryKind k, const Vec4& p, const Vec4& v, double t) {
  switch (k) {
    case GeometryKind::Hyperbolic: {  // tanh keeps large t finite
      const double tanh_t = std::tanh(t);
      return p.w * tanh_t / (p.w + v.w * tanh_t);
    }
    case GeometryKind::Spherical:
      return p.w * std::sin(t) / (p.w * std::cos(t) + v.w * std::sin(t));
    default: return t;
  }
}

double distance_from_chart_parameter(GeometryKind k, const Vec4& p, const Vec4& v, double s) {
  switch (k) {
    case GeometryKind::Hyperbolic: return std::atanh(s * p.w / (p.w - s * v.w));
    // (s |p.w|, |p.w| - s v.w sign p.w) is a positive multiple of (sin t, cos t) while the
    // geodesic stays in p's hemisphere, so atan2 goes on past pi/2 there.
    case GeometryKind::Spherical: {
      const double w = std::abs(p.w);
      return std::atan2(s * w, w - s * (p.w < 0 ? -v.w : v.w));
    }
    default: return s;
  }
}

SphereRoots sphere_roots(GeometryKind k, const Vec4& p, const Vec4& v, const Vec4& c, double r) {
  SphereRoots roots;
  if (k == GeometryKind::Euclidean) {
    // Closest approach (Ray Tracing Gems ch. 7): the discriminant from the vector l.
    const Vec3 f = p.xyz() - c.xyz(), d = v.xyz();
    const double b = -dot(f, d);
    const Vec3 l = f + b * d;  // from the centre to the line's closest point
    roots.disc = r * r - dot(l, l);
    if (roots.disc < 0) return roots;
    // sqrt(disc) takes b's sign so the sum never cancels; t0 t1 = |f|^2 - r^2.
    const double q = b + (b >= 0 ? 1.0 : -1.0) * std::sqrt(roots.disc);
    roots.t0 = q != 0 ? (dot(f, f) - r * r) / q : 0.0;
    roots.t1 = q;
    if (roots.t0 > roots.t1) std::swap(roots.t0, roots.t1);
    return roots;
  }
  // A C(t) + B S(t) = C(r), A = K <p,c>, B = K <v,c> (the left side is K <geodesic(t), c>).
  // c = A p + K B v + n with n perpendicular to p and v: |n| is sinh or sin of the distance
  // from c to the geodesic, the stable source of the discriminant.
  const double kk = curvature(k), a = kk * inner(k, p, c), b = kk * inner(k, v, c);
  const Vec4 n = c - a * p - kk * b * v;
  const double nn = std::max(0.0, inner(k, n, n));
  const auto [cos_r, sin_r] = trig(k, r);
  roots.disc = sin_r * sin_r - nn;
  if (roots.disc < 0) return roots;
  const double root = std::sqrt(roots.disc);
  if (k == GeometryKind::Hyperbolic) {
    // (A+B) u^2 - 2 C u + (A-B) = 0 in u = e^t. Of A -+ B (both >= e^-d) take the one
    // without cancellation, the other from (A-B)(A+B) = 1 + |n|^2.
    const double e = cos_r + root, product = 1 + nn;
    const double minus = b <= 0 ? a - b : product / (a + b);
    const double plus = b <= 0 ? product / (a - b) : a + b;
    roots.t0 = std::log(minus / e);
    roots.t1 = std::log(e / plus);
  } else {
    // A cos t + B sin t = rho cos(t - phi), rho^2 - cos^2 r = disc.
    const double phi = std::atan2(b, a), spread = std::atan2(root, cos_r);
    roots.t0 = phi - spread;
    roots.t1 = phi + spread;
  }
  return roots;
}

std::optional<double> intersect_sphere(GeometryKind k, const Vec4& p, const Vec4& v,
                                       const Vec4& c, double r, double t_min, double t_max) {
  const SphereRoots roots = sphere_roots(k, p, v, c, r);
  if (roots.disc < 0) return std::nullopt;
  if (k == GeometryKind::Spherical) {  // the geodesic comes round every 2 pi
    const double t = std::min(next_turn_after(roots.t0, t_min), next_turn_after(roots.t1, t_min));
    return t < t_max ? std::optional(t) : std::nullopt;
  }
  if (roots.t0 > t_min && roots.t0 < t_max) return roots.t0;
  if (roots.t1 > t_min && roots.t1 < t_max) return roots.t1;
  return std::nullopt;
}

double surface_offset_length(GeometryKind k, const Vec4& q) {
  double scale = max_abs(Vec3{q.x, q.y, q.z});
  if (k != GeometryKind::Euclidean) scale = std::max(scale, std::abs(q.w));  // E3: w = 1 exactly
  return 1e-4 + 0x1p-15 * scale;
}

Vec4 offset_from_surface(GeometryKind k, const Vec4& q, const Vec4& n) {
  return normalize_point(k, geodesic_point(k, q, n, surface_offset_length(k, q)));
}

Vec4 parallel_transport(GeometryKind k, const Vec4& p, const Vec4& v, double t, const Vec4& u) {
  // The component along v turns with the geodesic; the perpendicular part is constant.
  return u + inner(k, u, v) * (geodesic_tangent(k, p, v, t) - v);
}

std::optional<ChartTriangleHit> intersect_chart_triangle(const Vec3& o, const Vec3& d,
                                                         const Vec3& a, const Vec3& b,
                                                         const Vec3& c, double s_min,
                                                         double s_max) {
  // Woop, Benthin and Wald's watertight test: the frame's z axis along d's largest component
  // (x and y swapped where it is negative), the corners relative to o sheared so that d
  // becomes z, then the signed areas U, V, W of the line's point against the edges bc, ca, ab.
  const double dc[3] = {d.x, d.y, d.z};
  const double ad[3] = {std::abs(d.x), std::abs(d.y), std::abs(d.z)};
  const int z = ad[0] > ad[1] ? (ad[0] > ad[2] ? 0 : 2) : (ad[1] > ad[2] ? 1 : 2);
  int x = (z + 1) % 3, y = (x + 1) % 3;
  if (dc[z] < 0) std::swap(x, y);
  const double shear_x = -dc[x] / dc[z], shear_y = -dc[y] / dc[z], shear_z = 1 / dc[z];
  struct Sheared {
    double x, y, z;
  };
  const auto shear = [&](const Vec3& p) {
    const Vec3 r = p - o;
    const double q[3] = {r.x, r.y, r.z};
    return Sheared{q[x] + shear_x * q[z], q[y] + shear_y * q[z], q[z]};
  };
  const Sheared A = shear(a), B = shear(b), C = shear(c);
  const double U = C.x * B.y - C.y * B.x, V = A.x * C.y - A.y * C.x, W = B.x * A.y - B.y * A.x;
  if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return std::nullopt;
  const double det = U + V + W;
  if (det == 0) return std::nullopt;  // the line in the triangle's plane, or no triangle
  const double hit = (U * A.z + V * B.z + W * C.z) * shear_z / det;
  if (!(hit > s_min && hit <= s_max)) return std::nullopt;
  return ChartTriangleHit{hit, V / det, W / det};
}

}  // namespace geodesic::model
