#include "geometry/wide_isometry.h"

namespace geodesic {
namespace {

// The model's operations on column vectors of any precision: normalize_point as model.cpp's,
// then the projection onto a tangent space and the Gram–Schmidt that reorthonormalize uses.
template <class T>
using V4 = std::array<T, 4>;
template <class T>
using M4 = std::array<std::array<T, 4>, 4>;

double root(double x) { return std::sqrt(x); }
WideFloat root(WideFloat x) {  // two Newton steps from double's root: 53 -> 106 -> 113 bits
  if (!(x > 0)) return 0;
  WideFloat y = std::sqrt(double(x));
  for (int i = 0; i < 2; ++i) y = (y + x / y) / 2;
  return y;
}

template <class T>
T inner(GeometryKind k, const V4<T>& a, const V4<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + T(model::curvature(k)) * a[3] * b[3];
}

template <class T>
V4<T> normalize_point(GeometryKind k, V4<T> p) {
  switch (k) {
    case GeometryKind::Hyperbolic:  // w from xyz: -<p,p> cancels far out
      p[3] = root(1 + p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      return p;
    case GeometryKind::Spherical: {
      const T n = root(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
      for (T& c : p) c /= n;
      return p;
    }
    default: p[3] = 1; return p;
  }
}

// The part of v tangent at p, projected along the form's normal J p = (p.xyz, K p.w) (in H3 the
// Euclidean normal of the tangent space): a vector rounded far out moves by its own round-off.
// Projecting along p instead, as tangent_part does near the origin, would move it by
// <v, p> p ~ u e^(2D): far out p and the frame's boost direction are nearly parallel.
template <class T>
V4<T> tangent(GeometryKind k, const V4<T>& p, V4<T> v) {
  if (k == GeometryKind::Euclidean) {
    v[3] = 0;
    return v;
  }
  const T kk = T(model::curvature(k));
  const V4<T> normal{p[0], p[1], p[2], kk * p[3]};
  const T along = inner(k, v, p) / (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
  for (int i = 0; i < 4; ++i) v[i] -= along * normal[i];
  return v;
}

template <class T>
V4<T> column(const M4<T>& m, int c) {
  return {m[0][c], m[1][c], m[2][c], m[3][c]};
}

template <class T>
void set_column(M4<T>& m, int c, const V4<T>& v) {
  for (int r = 0; r < 4; ++r) m[r][c] = v[r];
}

// Columns 0-2 made tangent first, then Gram–Schmidt in the form, which is positive definite
// and well conditioned on the tangent space (not across it, far out in H3).
template <class T>
M4<T> orthonormal(GeometryKind k, const M4<T>& g) {
  M4<T> r{};
  const V4<T> p = normalize_point(k, column(g, 3));
  set_column(r, 3, p);
  for (int i = 0; i < 3; ++i) {
    V4<T> u = tangent(k, p, column(g, i));
    for (int j = 0; j < i; ++j) {
      const V4<T> f = column(r, j);
      const T along = inner(k, u, f);
      for (int c = 0; c < 4; ++c) u[c] -= along * f[c];
    }
    const T n2 = inner(k, u, u);
    const T scale = n2 > 0 ? 1 / root(n2) : T(0);
    for (T& c : u) c *= scale;
    set_column(r, i, u);
  }
  return r;
}

template <class T>
M4<T> product(const M4<T>& a, const M4<T>& b) {
  M4<T> r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int c = 0; c < 4; ++c) r[i][j] += a[i][c] * b[c][j];
  return r;
}

template <class T>
V4<T> product(const M4<T>& a, const V4<T>& v) {
  V4<T> r{};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 4; ++c) r[i] += a[i][c] * v[c];
  return r;
}

template <class T>
M4<T> widen(const Mat4& g) {
  M4<T> r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r[i][j] = T(g.m[i][j]);
  return r;
}

template <class T>
Mat4 narrow(const M4<T>& m) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = double(m[i][j]);
  return r;
}

// Double loses u |g| |p| on g p, binary128 only the u |p| that p's own rounding costs: an H3
// isometry carrying the origin further than ~7.6 (entries above 2^10) is held wide.
bool needs_wide(GeometryKind k, const Mat4& g) {
  return k == GeometryKind::Hyperbolic && g.max_abs() > 1024;
}

}  // namespace

WideIsometry::WideIsometry(GeometryKind k, const Mat4& g)
    : WideIsometry(k,
                   needs_wide(k, g) ? orthonormal(k, widen<WideFloat>(g))
                                    : widen<WideFloat>(narrow(orthonormal(k, widen<double>(g)))),
                   needs_wide(k, g)) {}

WideIsometry::WideIsometry(GeometryKind k, const Matrix& m, bool wide)
    : kind_(k), wide_(wide), matrix_(m), rounded_(narrow(m)) {}

WideIsometry WideIsometry::inverse() const {
  Matrix r{};
  if (kind_ == GeometryKind::Euclidean) {  // [R t; 0 1] -> [R^T  -R^T t; 0 1]
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) r[i][j] = matrix_[j][i];
      for (int j = 0; j < 3; ++j) r[i][3] -= matrix_[j][i] * matrix_[j][3];
    }
    r[3][3] = 1;
    return {kind_, r, wide_};
  }
  // S3: g^T. H3: J g^T J with J = diag(1, 1, 1, -1).
  const WideFloat sign = kind_ == GeometryKind::Hyperbolic ? -1 : 1;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r[i][j] = matrix_[j][i] * ((i == 3) != (j == 3) ? sign : 1);
  return {kind_, r, wide_};
}

WideIsometry WideIsometry::operator*(const WideIsometry& other) const {
  return {kind_, product(matrix_, other.matrix_), wide_ || other.wide_};
}

Vec4 WideIsometry::apply(const Vec4& point) const {
  if (!wide_) return model::normalize_point(kind_, rounded_ * model::normalize_point(kind_, point));
  const V4<WideFloat> p = normalize_point(kind_, V4<WideFloat>{point.x, point.y, point.z, point.w});
  const V4<WideFloat> q = normalize_point(kind_, product(matrix_, p));
  return {double(q[0]), double(q[1]), double(q[2]), double(q[3])};
}

Mat4 WideIsometry::apply(const Mat4& pose) const {
  if (!wide_ && !needs_wide(kind_, pose))
    return narrow(orthonormal(kind_, widen<double>(rounded_ * pose)));
  return narrow(orthonormal(kind_, product(matrix_, orthonormal(kind_, widen<WideFloat>(pose)))));
}

}  // namespace geodesic
