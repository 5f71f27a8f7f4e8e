#include "geometry/sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace geodesic {

TangentFrame orthonormal_basis(const Vec3& n) {
  const double s = n.z >= 0.0 ? 1.0 : -1.0;
  const double a = -1.0 / (s + n.z);
  const double c = n.x * n.y * a;
  return {{1.0 + s * n.x * n.x * a, s * c, -s * n.x}, {c, s + n.y * n.y * a, -n.y}};
}

Vec3 sample_cosine_hemisphere(const Vec3& n, double u1, double u2) {
  const double r = std::sqrt(u1);
  const double phi = 2.0 * std::numbers::pi * u2;
  const TangentFrame frame = orthonormal_basis(n);
  return normalize(r * std::cos(phi) * frame.tangent + r * std::sin(phi) * frame.bitangent +
                   std::sqrt(std::max(0.0, 1.0 - u1)) * n);
}

double cosine_hemisphere_pdf(const Vec3& n, const Vec3& w) {
  return std::max(0.0, dot(n, w)) / std::numbers::pi;
}

namespace {

// The unit vector at polar angle acos(cos_theta), azimuth phi around the unit axis.
Vec3 around(const Vec3& axis, double cos_theta, double phi) {
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  const TangentFrame frame = orthonormal_basis(axis);
  return normalize(sin_theta * std::cos(phi) * frame.tangent +
                   sin_theta * std::sin(phi) * frame.bitangent + cos_theta * axis);
}

}  // namespace

Vec3 sample_phong_lobe(const Vec3& r, double exponent, double u1, double u2) {
  // The cdf of cos(alpha) is cos^(e+1): invert it. 1 - u1 keeps u1 = 0 off cos = 0.
  return around(r, std::pow(1.0 - u1, 1.0 / (exponent + 1.0)), 2.0 * std::numbers::pi * u2);
}

double phong_lobe_pdf(const Vec3& r, double exponent, const Vec3& w) {
  const double c = dot(r, w);
  return c <= 0 ? 0 : (exponent + 1.0) / (2.0 * std::numbers::pi) * std::pow(c, exponent);
}

Vec3 sample_uniform_cone(const Vec3& axis, double cos_max, double u1, double u2) {
  return around(axis, 1.0 - u1 * (1.0 - cos_max), 2.0 * std::numbers::pi * u2);
}

double uniform_cone_pdf(const Vec3& axis, double cos_max, const Vec3& w) {
  return dot(axis, w) >= cos_max ? 1.0 / (2.0 * std::numbers::pi * (1.0 - cos_max)) : 0.0;
}

Barycentrics sample_uniform_triangle(double u1, double u2) {
  const double s = std::sqrt(u1);
  return {1.0 - s, u2 * s};
}

double fresnel_dielectric(double cos_i, double eta) {
  const double sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0) return 1.0;
  const double cos_t = std::sqrt(1.0 - sin2_t);
  const double parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const double perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5 * (parallel * parallel + perpendicular * perpendicular);
}

double power_heuristic(double a, double b) {
  if (a <= 0) return 0;
  if (!std::isfinite(a)) return 1;
  return a * a / (a * a + b * b);
}

double luminance(const Vec3& rgb) { return dot(rgb, {0.2126, 0.7152, 0.0722}); }

}  // namespace geodesic
