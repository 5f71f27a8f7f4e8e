// Isometries of H3 given as Moebius transformations of its sphere at infinity, the form
// SnapPy prints (M.fundamental_group().SL2C(word)) and the literature writes cusped groups in:
// z -> (a z + b) / (c z + d) on the upper half-space's boundary C u {inf}, or, reversing
// orientation, z -> (a conj(z) + b) / (c conj(z) + d).
//
// A point (x, y, z, w) of the hyperboloid is the Hermitian matrix X = [[w + z, x + i y],
// [x - i y, w - z]] (det X = w^2 - x^2 - y^2 - z^2 = 1), on which A in SL(2, C) acts as
// X -> A X A^*. A boundary point zeta is the null vector of X = (zeta, 1)(zeta, 1)^*: infinity
// is the Klein ball's north pole (0, 0, 1), zero its south pole, the unit circle its equator.
// Conjugating z first is the reflection y -> -y.
#pragma once

#include <array>
#include <complex>

#include "geometry/vec.h"

namespace geodesic {

using Complex = std::complex<double>;

struct Moebius {
  std::array<Complex, 4> abcd;  // [[a, b], [c, d]], row by row; det = ad - bc != 0
  bool reverses = false;        // acts on conj(z): orientation-reversing
};

// The O(3,1) matrix (column vectors, w last) of the transformation; det(A) is first scaled to 1
// (A and -A give the same isometry). Assumes det != 0.
Mat4 moebius_isometry(const Moebius& t);

// The hyperboloid null vector (w = 1) of a boundary point; infinity is {0, 0, 1, 1}.
Vec4 boundary_point(Complex zeta);
Vec4 boundary_infinity();

}  // namespace geodesic
