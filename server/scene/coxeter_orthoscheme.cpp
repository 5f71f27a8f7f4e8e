#include "scene/coxeter_orthoscheme.h"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "geometry/model.h"
#include "scene/scene.h"

namespace geodesic {
namespace {

constexpr double kPi = std::numbers::pi;

// x -> x - 2 <x, e> e for a unit spacelike e, with <a, b> = a.xyz b.xyz - a.w b.w.
Mat4 reflection(const Vec4& e) {
  const double v[4] = {e.x, e.y, e.z, e.w}, dual[4] = {e.x, e.y, e.z, -e.w};
  Mat4 g = Mat4::identity();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) g.m[r][c] -= 2 * v[r] * dual[c];
  return g;
}

// The vector u with n_i . u = 0 for three covectors n_i (cofactors of the 3 x 4 matrix).
Vec4 common_kernel(const std::array<std::array<double, 4>, 3>& n) {
  double u[4];
  for (int i = 0; i < 4; ++i) {
    int c[3], k = 0;
    for (int j = 0; j < 4; ++j)
      if (j != i) c[k++] = j;
    const double det = n[0][c[0]] * (n[1][c[1]] * n[2][c[2]] - n[1][c[2]] * n[2][c[1]]) -
                       n[0][c[1]] * (n[1][c[0]] * n[2][c[2]] - n[1][c[2]] * n[2][c[0]]) +
                       n[0][c[2]] * (n[1][c[0]] * n[2][c[1]] - n[1][c[1]] * n[2][c[0]]);
    u[i] = i % 2 ? -det : det;
  }
  return {u[0], u[1], u[2], u[3]};
}

// A timelike vector scaled onto the upper sheet w = sqrt(1 + |xyz|^2).
Vec4 on_hyperboloid(const Vec4& v) {
  const double scale = std::sqrt(v.w * v.w - dot(v.xyz(), v.xyz()));
  return (v.w < 0 ? -1 : 1) / scale * v;
}

// The vertices lie on three mirrors each, so the origin (and the nudges the Dirichlet domain
// tries off it) must not: the group is conjugated to centre the tetrahedron's vertex centroid.
std::vector<Mat4> centred(const std::vector<Vec4>& normals) {
  constexpr auto kH3 = GeometryKind::Hyperbolic;
  Vec4 sum{0, 0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    std::array<std::array<double, 4>, 3> dual;
    for (int j = 0, row = 0; j < 4; ++j)
      if (j != k) dual[row++] = {normals[j].x, normals[j].y, normals[j].z, -normals[j].w};
    const Vec4 v = on_hyperboloid(common_kernel(dual));
    sum = sum + v;
  }
  const Mat4 move = model::translation_from(kH3, on_hyperboloid(sum));
  const Mat4 back = model::inverse_isometry(kH3, move);
  std::vector<Mat4> generators;
  for (const Vec4& e : normals) generators.push_back(model::reorthonormalize(kH3, move * reflection(e) * back));
  return generators;
}

}  // namespace

std::vector<Mat4> coxeter_orthoscheme_generators(int p, int q, int r) {
  const std::string name = "Coxeter orthoscheme [" + std::to_string(p) + "," + std::to_string(q) +
                           "," + std::to_string(r) + "]";
  if (p < 3 || q < 3 || r < 3 || 1.0 / p + 1.0 / q <= 0.5 || 1.0 / q + 1.0 / r <= 0.5)
    throw SceneError(name + ": [p, q] and [q, r] must be finite reflection groups (1/p + 1/q > 1/2, "
                     "p, q, r >= 3), or the tetrahedron has ideal or hyperideal vertices");
  // Unit normals e_i with <e_i, e_j> = -cos(pi / m_ij) (the Gram matrix of the diagram), built
  // one coordinate at a time: e1, e2 in the xy plane, e3 in the yz plane, e4 in the zw plane.
  const double a = kPi / p, b = kPi / q, c = kPi / r;
  const double y3 = -std::cos(b) / std::sin(a), z3 = std::sqrt(1 - y3 * y3);
  const double z4 = -std::cos(c) / z3;
  if (!(z4 * z4 > 1 + 1e-12))
    throw SceneError(name + ": spherical or Euclidean, not hyperbolic (the Gram matrix has no "
                     "time direction)");
  return centred({{1, 0, 0, 0}, {-std::cos(a), std::sin(a), 0, 0}, {0, y3, z3, 0},
                  {0, 0, z4, std::sqrt(z4 * z4 - 1)}});
}

double lobachevsky(double x) {
  x = std::fmod(x, kPi);
  if (x < 0) x += kPi;
  if (x > kPi / 2) return -lobachevsky(kPi - x);
  if (x == 0) return 0;
  // log|2 sin t| = log(2t) + log(sin t / t): the first integrates in closed form, the second is
  // smooth on [0, pi/2] (composite Simpson, error ~ h^4).
  constexpr int n = 2000;
  const double h = x / n;
  auto smooth = [](double t) { return t > 0 ? std::log(std::sin(t) / t) : 0.0; };
  double sum = smooth(0) + smooth(x);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * smooth(i * h);
  return -(sum * h / 3 + x * std::log(2 * x) - x);
}

double orthoscheme_volume(int p, int q, int r) {
  const double a = kPi / p, b = kPi / q, c = kPi / r;
  const double s = std::cos(b) * std::cos(b) - std::sin(a) * std::sin(a) * std::sin(c) * std::sin(c);
  const double d = std::atan(std::sqrt(s) / (std::cos(a) * std::cos(c)));
  return (lobachevsky(a + d) - lobachevsky(a - d) + lobachevsky(c + d) - lobachevsky(c - d) -
          lobachevsky(kPi / 2 - b + d) + lobachevsky(kPi / 2 - b - d) + 2 * lobachevsky(kPi / 2 - d)) /
         4;
}

}  // namespace geodesic
