#include "scene/domain_volume.h"

#include <array>
#include <cmath>

namespace geodesic {
namespace {

// Integral of the chart's volume density over the radius, int_0^r rho(s) s^2 ds.
double radial(GeometryKind kind, double r) {
  switch (kind) {
    case GeometryKind::Hyperbolic: return (r / (1 - r * r) - std::atanh(r)) / 2;
    case GeometryKind::Spherical: return (std::atan(r) - r / (1 + r * r)) / 2;
    case GeometryKind::Euclidean: break;
  }
  return r * r * r / 3;
}

// 8-point Gauss-Legendre on [0, 1].
constexpr std::array<double, 8> kNodes = {0.019855071751231856, 0.10166676129318664,
                                          0.2372337950418355,   0.4082826787521751,
                                          0.5917173212478249,   0.7627662049581645,
                                          0.8983332387068134,   0.9801449282487681};
constexpr std::array<double, 8> kWeights = {0.05061426814518813, 0.11119051722668724,
                                            0.15685332293894363, 0.18134189168918100,
                                            0.18134189168918100, 0.15685332293894363,
                                            0.11119051722668724, 0.05061426814518813};

// Volume of the cone from the origin over triangle abc: the solid-angle element of a point P
// of the triangle is h dA / |P|^3 (h: the plane's distance from the origin), and along that
// direction the cone holds radial(|P|). `depth` levels of uniform splitting into four, then
// `corner` more levels of splitting only the triangle at corner a (an ideal vertex, see below).
double cone(GeometryKind kind, const Vec3& a, const Vec3& b, const Vec3& c, int depth, int corner) {
  const Vec3 ab = (a + b) / 2.0, bc = (b + c) / 2.0, ca = (c + a) / 2.0;
  if (depth > 0)
    return cone(kind, a, ab, ca, depth - 1, corner) + cone(kind, ab, b, bc, depth - 1, 0) +
           cone(kind, ca, bc, c, depth - 1, 0) + cone(kind, ab, bc, ca, depth - 1, 0);
  if (corner > 0)
    return cone(kind, a, ab, ca, 0, corner - 1) + cone(kind, ab, b, bc, 0, 0) +
           cone(kind, ca, bc, c, 0, 0) + cone(kind, ab, bc, ca, 0, 0);
  const Vec3 n = cross(b - a, c - a);
  const double twice_area = length(n);
  if (twice_area == 0) return 0;
  const double h = dot(a, n) / twice_area;
  double sum = 0;
  // Collapsed (Duffy) coordinates: P = a + u (b - a) + u v (c - b), dA = u * 2 area du dv.
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const double u = kNodes[i], v = kNodes[j];
      const Vec3 p = a + u * (b - a) + u * v * (c - b);
      const double r = length(p);
      sum += kWeights[i] * kWeights[j] * u * radial(kind, r) / (r * r * r);
    }
  return sum * twice_area * h;
}

// A triangle whose corners may be ideal (H3 cusp tips on the sphere at infinity, where radial
// grows like 1 / (1 - |P|)): each ideal corner is put at the collapsed vertex of the Duffy map,
// whose Jacobian u cancels that growth to a function of the direction from a alone, resolved
// by cutting the triangle into 8 fans about a, and each fan is split towards a 40 times more
// to resolve the remaining u log u; a triangle with several is first split between them.
double triangle(GeometryKind kind, const std::array<Vec3, 3>& corners, const std::array<bool, 3>& ideal) {
  constexpr int kDepth = 2, kCorner = 40, kFan = 8;
  const int count = int(ideal[0]) + int(ideal[1]) + int(ideal[2]);
  if (count == 0) return cone(kind, corners[0], corners[1], corners[2], kDepth, 0);
  for (int i = 0; i < 3; ++i) {
    const Vec3 &a = corners[i], &b = corners[(i + 1) % 3], &c = corners[(i + 2) % 3];
    const bool ib = ideal[(i + 1) % 3], ic = ideal[(i + 2) % 3];
    if (!ideal[i]) continue;
    if (count == 1) {  // in fans about a: the integrand's growth depends on the direction
      double sum = 0;
      for (int k = 0; k < kFan; ++k)
        sum += cone(kind, a, b + (c - b) * (double(k) / kFan), b + (c - b) * (double(k + 1) / kFan),
                    kDepth, kCorner);
      return sum;
    }
    // Split the edge from a to its next ideal corner at the midpoint (inside the ball).
    if (ib) {
      const Vec3 m = (a + b) / 2.0;
      return triangle(kind, {a, m, c}, {true, false, ic}) + triangle(kind, {m, b, c}, {false, true, ic});
    }
    const Vec3 m = (a + c) / 2.0;
    return triangle(kind, {a, b, m}, {true, ib, false}) + triangle(kind, {m, b, c}, {false, ib, true});
  }
  return 0;
}

}  // namespace

double domain_volume(GeometryKind kind, const Polyhedron& p) {
  double volume = 0;
  auto corner = [&](int i) {  // an ideal vertex exactly on the sphere
    return ideal_vertex(kind, p.vertices[i]) ? normalize(p.vertices[i]) : p.vertices[i];
  };
  for (const auto& face : p.faces) {
    if (face.size() < 3) continue;
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      const int k[3] = {face[0], face[i], face[i + 1]};
      volume += triangle(kind, {corner(k[0]), corner(k[1]), corner(k[2])},
                         {ideal_vertex(kind, p.vertices[k[0]]), ideal_vertex(kind, p.vertices[k[1]]),
                          ideal_vertex(kind, p.vertices[k[2]])});
    }
  }
  return volume;
}

}  // namespace geodesic
