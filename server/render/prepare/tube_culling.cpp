#include "render/prepare/tube_culling.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace geodesic {

uint32_t near_faces(const Cell& cell, const Vec3& o, const Vec3& d, double s_max, double reach) {
  uint32_t near = 0;
  double lo = 0, hi = s_max;  // where every near face is within reach at once
  for (size_t i = 0; i < std::min<size_t>(cell.faces.size(), 32); ++i) {
    const CellFace& f = cell.faces[i];
    const double beyond = f.delta - dot(f.normal, o) - reach, towards = dot(f.normal, d);
    if (beyond > 0 && beyond > s_max * towards) continue;
    near |= 1u << i;
    if (towards > 0) lo = std::max(lo, beyond / towards);
    if (towards < 0) hi = std::min(hi, beyond / towards);
  }
  return std::popcount(near) < 3 && lo > hi + near_span_slack(s_max) ? 0 : near;
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

std::vector<uint32_t> tubes_to_test(const gpu::Cell& cell, std::span<const gpu::CellFace> faces,
                                    uint32_t near) {
  std::vector<uint32_t> tested;
  for (uint32_t pending = near; pending != 0; pending &= pending - 1) {
    const gpu::CellFace& face = faces[cell.face_begin + std::countr_zero(pending)];
    for (uint32_t pairs = face.tube_partners & near; pairs != 0; pairs &= pairs - 1) {
      const uint32_t below = (1u << std::countr_zero(pairs)) - 1;
      tested.push_back(cell.tube_begin + face.tubes + std::popcount(face.tube_partners & below));
    }
  }
  for (uint32_t i = cell.always_begin; i < cell.tube_count; ++i)
    tested.push_back(cell.tube_begin + i);
  return tested;
}

}  // namespace geodesic
