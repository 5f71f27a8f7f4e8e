// Which edge tubes a chart segment can meet, from the cell's faces alone (the double twin of
// nearestTube's culling in shaders/primitives/edge_tube.glsl). A tube lies within its radius of
// its edge, and the edge lies in the planes of two faces, so a point of the tube is within the
// radius of both planes. Along the segment o + s d, s in [0, s_max], a face's distance
// h(s) = delta - n . (o + s d) is linear, smallest at an end: a face is near when that smallest
// value is at most the cell's largest tube radius, and a tube can be met only when both of its
// faces are near, and only where both are near at once: each near face is near over one
// interval of s, and when the near faces are at most two and their intervals do not meet (past
// near_span_slack), none is counted near. A segment that enters by one face and leaves by
// another, far from the edges, is near the first only at its start and the second only at its
// end, so tests no tube instead of all of them; one that passes an edge tests the tubes found
// from its pairs of near faces without reading the cell's other tubes.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/gpu_types.h"
#include "render/prepare/cells.h"

namespace geodesic {

// GpuTube's face index when no two of the cell's first 32 faces hold the axis: always tested.
constexpr uint32_t kAlwaysTest = ~0u;

// The margin by which the near faces' intervals must miss each other before none is counted
// near: far beyond float round-off, a ten-thousandth of the segment and a millionth of the chart.
constexpr double near_span_slack(double s_max) { return 1e-4 * s_max + 1e-6; }

// Bit i set when the cell's local face i (i < 32) is near the segment (none when at most two
// are, never near at once).
uint32_t near_faces(const Cell& cell, const Vec3& o, const Vec3& d, double s_max, double reach);

// Two local faces of the cell whose planes hold the chart segment [a, b] (to within 1e-7 of
// the chart's scale), or kAlwaysTest twice.
std::pair<uint32_t, uint32_t> faces_holding(const Cell& cell, const Vec3& a, const Vec3& b);

// Whether a tube held by faces (face_a, face_b) can meet a segment whose near faces are `near`.
constexpr bool tube_may_meet(uint32_t near, uint32_t face_a, uint32_t face_b) {
  return face_a >= 32 || face_b >= 32 || ((near >> face_a) & (near >> face_b) & 1u) != 0;
}

// The packed cell's tubes (indices into the packed tube array) that nearestTube tests for a
// segment whose near faces are `near` (bits below the cell's face count): for each near face,
// the tube on each of its pairs with another near face, found from the face's tube_partners
// (gpu_types.h CellFace), then those always tested; the order is the shader's.
std::vector<uint32_t> tubes_to_test(const gpu::Cell& cell, std::span<const gpu::CellFace> faces,
                                    uint32_t near);

}  // namespace geodesic
