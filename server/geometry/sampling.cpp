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

double luminance(const Vec3& rgb) { return dot(rgb, {0.2126, 0.7152, 0.0722}); }

}  // namespace geodesic
