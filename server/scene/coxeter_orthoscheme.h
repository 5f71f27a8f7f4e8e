// Compact hyperbolic Coxeter orthoschemes [p, q, r]: the tetrahedra whose dihedral angles are
// pi / p, pi / q, pi / r along a path of three edges and pi / 2 at the other three. The
// reflections in their faces generate a discrete group (a kaleidoscope, Coxeter 1934) whose
// quotient orbifold is the tetrahedron itself; [p, q] and [q, r] are the symmetry groups of the
// regular polyhedron {p, q} and of its vertex figure, so the regular polyhedron {p, q} with
// dihedral angle 2 pi / r is made of (number of its flags) copies: 120 for the dodecahedron.
#pragma once

#include <vector>

#include "geometry/vec.h"

namespace geodesic {

// The four reflections, as O(3,1) matrices on column vectors (w last). Throws SceneError unless
// [p, q, r] is a compact hyperbolic Coxeter simplex: [3,5,3], [4,3,5], [5,3,4] or [5,3,5].
std::vector<Mat4> coxeter_orthoscheme_generators(int p, int q, int r);

// Lobachevsky's function L(x) = -integral_0^x log|2 sin t| dt (pi-periodic and odd), to ~1e-12.
double lobachevsky(double x);

// The volume of the orthoscheme [p, q, r], by Lobachevsky's formula (Ratcliffe, Foundations of
// Hyperbolic Manifolds, theorem 10.4.4): with a = pi/p, b = pi/q, c = pi/r and
// delta = atan(sqrt(cos^2 b - sin^2 a sin^2 c) / (cos a cos c)),
//   V = (L(a+delta) - L(a-delta) + L(c+delta) - L(c-delta) - L(pi/2-b+delta)
//        + L(pi/2-b-delta) + 2 L(pi/2-delta)) / 4.
double orthoscheme_volume(int p, int q, int r);

}  // namespace geodesic
