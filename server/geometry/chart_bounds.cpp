#include "geometry/chart_bounds.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace geodesic {
namespace {

using Matrix = std::array<std::array<double, 4>, 4>;

// Gauss-Jordan inverse with partial pivoting; nothing when (numerically) singular.
std::optional<Matrix> invert(Matrix a) {
  Matrix inv{};
  for (int i = 0; i < 4; ++i) inv[i][i] = 1;
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (std::abs(a[pivot][col]) < 1e-300) return std::nullopt;
    std::swap(a[col], a[pivot]);
    std::swap(inv[col], inv[pivot]);
    const double scale = 1 / a[col][col];
    for (int c = 0; c < 4; ++c) {
      a[col][c] *= scale;
      inv[col][c] *= scale;
    }
    for (int r = 0; r < 4; ++r) {
      if (r == col) continue;
      const double f = a[r][col];
      for (int c = 0; c < 4; ++c) {
        a[r][c] -= f * a[col][c];
        inv[r][c] -= f * inv[col][c];
      }
    }
  }
  return inv;
}

}  // namespace

std::optional<ChartBox> sphere_chart_box(GeometryKind k, const Vec4& c, double r) {
  if (k == GeometryKind::Euclidean) {
    const Vec3 centre = c.xyz();
    return ChartBox{centre - Vec3(r, r, r), centre + Vec3(r, r, r)};
  }
  const double cv[4] = {c.x, c.y, c.z, c.w};
  Matrix q{};
  if (k == GeometryKind::Hyperbolic) {
    // -<q, c> <= cosh r with q = Y / sqrt(-<Y, Y>): (Jc)(Jc)^T + cosh^2 r J.
    const double jc[4] = {cv[0], cv[1], cv[2], -cv[3]};
    const double ch2 = std::cosh(r) * std::cosh(r);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) q[i][j] = jc[i] * jc[j] + (i == j ? (i == 3 ? -ch2 : ch2) : 0);
  } else {
    // q . c >= cos r with q = Y / |Y|: bounded only inside the open hemisphere w > 0.
    if (r >= std::numbers::pi / 2 || c.w <= std::sin(r)) return std::nullopt;
    const double c2 = std::cos(r) * std::cos(r);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) q[i][j] = (i == j ? c2 : 0) - cv[i] * cv[j];
  }
  const auto dual = invert(q);
  if (!dual) return std::nullopt;
  const Matrix& d = *dual;
  ChartBox box;
  double lo[3], hi[3];
  for (int i = 0; i < 3; ++i) {
    const double disc = d[i][3] * d[i][3] - d[i][i] * d[3][3];
    if (disc < 0 || d[3][3] == 0) return std::nullopt;
    const double a = (d[i][3] - std::sqrt(disc)) / d[3][3];
    const double b = (d[i][3] + std::sqrt(disc)) / d[3][3];
    lo[i] = std::min(a, b);
    hi[i] = std::max(a, b);
  }
  box.lo = {lo[0], lo[1], lo[2]};
  box.hi = {hi[0], hi[1], hi[2]};
  return box;
}

std::optional<ChartBox> intersect(const ChartBox& a, const ChartBox& b) {
  const ChartBox out{{std::max(a.lo.x, b.lo.x), std::max(a.lo.y, b.lo.y), std::max(a.lo.z, b.lo.z)},
                     {std::min(a.hi.x, b.hi.x), std::min(a.hi.y, b.hi.y), std::min(a.hi.z, b.hi.z)}};
  if (out.lo.x > out.hi.x || out.lo.y > out.hi.y || out.lo.z > out.hi.z) return std::nullopt;
  return out;
}

}  // namespace geodesic
