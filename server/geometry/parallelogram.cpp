#include "geometry/parallelogram.h"

#include <algorithm>
#include <cmath>

namespace geodesic {

std::optional<ChartParallelogramHit> intersect_chart_parallelogram(const Vec3& o, const Vec3& d,
                                                                   const Vec3& a, const Vec3& b,
                                                                   const Vec3& c, double s_min,
                                                                   double s_max) {
  const Vec3 u = b - a, v = c - b, n = cross(u, v);
  const Vec3 ao = a - o;  // first, as the triangle test does: o and a may be far out
  const double denom = dot(n, d);
  if (denom == 0) return std::nullopt;  // the line in the plane or parallel to it, or no area
  const double s = dot(n, ao) / denom;
  if (!(s > s_min && s <= s_max)) return std::nullopt;
  const Vec3 x = s * d - ao;  // the point, from a
  const double nn = dot(n, n);
  const double alpha = dot(cross(x, v), n) / nn, beta = dot(cross(u, x), n) / nn;
  // How far outside [0, 1] each lies (<= 0 inside), against m0 |v| / |n| and m0 |u| / |n|,
  // compared squared as the float twin does.
  const double out_a = std::max(-alpha, alpha - 1), out_b = std::max(-beta, beta - 1);
  const double m0 = 0x1p-18 * (1 + std::max(max_abs(o), max_abs(a)));
  if ((out_a > 0 && out_a * out_a * nn > m0 * m0 * dot(v, v)) ||
      (out_b > 0 && out_b * out_b * nn > m0 * m0 * dot(u, u)))
    return std::nullopt;
  return ChartParallelogramHit{s, alpha, beta};
}

PairedTriangleHit paired_triangle_hit(double alpha, double beta) {
  if (beta <= alpha) return {0, alpha - beta, beta};
  return {1, alpha, beta - alpha};
}

}  // namespace geodesic
