#include "geometry/moebius.h"

#include <cmath>

#include "geometry/model.h"

namespace geodesic {
namespace {

using Hermitian = std::array<Complex, 4>;  // [[p, q], [conj q, s]]

Hermitian hermitian(const Vec4& v) {
  return {Complex(v.w + v.z, 0), Complex(v.x, v.y), Complex(v.x, -v.y), Complex(v.w - v.z, 0)};
}

Vec4 point_of(const Hermitian& X) {
  return {X[1].real(), X[1].imag(), (X[0].real() - X[3].real()) / 2,
          (X[0].real() + X[3].real()) / 2};
}

// A X A^* for 2x2 matrices stored row by row.
Hermitian congruence(const std::array<Complex, 4>& A, const Hermitian& X) {
  const Complex ax0 = A[0] * X[0] + A[1] * X[2], ax1 = A[0] * X[1] + A[1] * X[3];
  const Complex ax2 = A[2] * X[0] + A[3] * X[2], ax3 = A[2] * X[1] + A[3] * X[3];
  return {ax0 * std::conj(A[0]) + ax1 * std::conj(A[1]), ax0 * std::conj(A[2]) + ax1 * std::conj(A[3]),
          ax2 * std::conj(A[0]) + ax3 * std::conj(A[1]), ax2 * std::conj(A[2]) + ax3 * std::conj(A[3])};
}

}  // namespace

Mat4 moebius_isometry(const Moebius& t) {
  std::array<Complex, 4> A = t.abcd;
  const Complex scale = std::sqrt(A[0] * A[3] - A[1] * A[2]);
  for (Complex& a : A) a /= scale;
  Mat4 g;
  const Vec4 basis[4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  for (int c = 0; c < 4; ++c) {
    Vec4 e = basis[c];
    if (t.reverses) e.y = -e.y;
    const Vec4 image = point_of(congruence(A, hermitian(e)));
    g.m[0][c] = image.x;
    g.m[1][c] = image.y;
    g.m[2][c] = image.z;
    g.m[3][c] = image.w;
  }
  return g;
}

Vec4 boundary_point(Complex zeta) {
  // (zeta, 1)(zeta, 1)^* = [[|zeta|^2, zeta], [conj zeta, 1]], scaled to w = 1.
  const double n = std::norm(zeta);
  return Vec4{zeta.real(), zeta.imag(), (n - 1) / 2, (n + 1) / 2} / ((n + 1) / 2);
}

Vec4 boundary_infinity() { return {0, 0, 1, 1}; }

}  // namespace geodesic
