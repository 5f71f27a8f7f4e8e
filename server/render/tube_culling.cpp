#include "render/tube_culling.h"

#include <algorithm>
#include <cmath>

namespace geodesic {

uint32_t near_faces(const Cell& cell, const Vec3& o, const Vec3& d, double s_max, double reach) {
  uint32_t near = 0;
  for (size_t i = 0; i < std::min<size_t>(cell.faces.size(), 32); ++i) {
    const CellFace& f = cell.faces[i];
    const double h0 = f.delta - dot(f.normal, o), h1 = f.delta - dot(f.normal, o + s_max * d);
    if (std::min(h0, h1) <= reach) near |= 1u << i;
  }
  return near;
}

std::pair<uint32_t, uint32_t> faces_holding(const Cell& cell, const Vec3& a, const Vec3& b) {
  std::vector<uint32_t> holding;
  for (size_t i = 0; i < std::min<size_t>(cell.faces.size(), 32) && holding.size() < 2; ++i) {
    const CellFace& f = cell.faces[i];
    const double tolerance = 1e-7 * (1 + std::abs(f.delta));
    if (std::abs(dot(f.normal, a) - f.delta) <= tolerance &&
        std::abs(dot(f.normal, b) - f.delta) <= tolerance)
      holding.push_back(uint32_t(i));
  }
  if (holding.size() < 2) return {kAlwaysTest, kAlwaysTest};
  return {holding[0], holding[1]};
}

}  // namespace geodesic
