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
// direction the cone holds radial(|P|).
double cone(GeometryKind kind, const Vec3& a, const Vec3& b, const Vec3& c, int depth) {
  if (depth > 0) {  // split into four: the integrand varies fast near the Klein horizon
    const Vec3 ab = (a + b) / 2.0, bc = (b + c) / 2.0, ca = (c + a) / 2.0;
    return cone(kind, a, ab, ca, depth - 1) + cone(kind, ab, b, bc, depth - 1) +
           cone(kind, ca, bc, c, depth - 1) + cone(kind, ab, bc, ca, depth - 1);
  }
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

}  // namespace

double domain_volume(GeometryKind kind, const Polyhedron& p) {
  double volume = 0;
  for (const auto& face : p.faces) {
    if (face.size() < 3) continue;
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
      volume += cone(kind, p.vertices[face[0]], p.vertices[face[i]], p.vertices[face[i + 1]], 2);
  }
  return volume;
}

}  // namespace geodesic
