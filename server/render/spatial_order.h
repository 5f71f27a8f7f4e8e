// Primitives in the order of a median-split tree over their centres. Some drivers build a
// bottom-level acceleration structure by splitting the primitive list at its middle index,
// without looking at positions (Mesa lavapipe: lvp_build_internal_node halves [first, last] at
// (first + last) / 2), so the tree is only as good as the order it is given: boxes listed mesh by
// mesh, or tubes edge by edge, give nodes whose boxes span the whole scene, and every traversal
// visits most of them. Listed in this order, that driver's index split is a spatial split at
// the same indices (along the longest axis of the centres' bounds): a kd-style tree. A driver
// with a builder of its own is unaffected.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/vec.h"

namespace geodesic {

// The permutation that lists `centres` so that halving every index range [first, last] at
// (first + last) / 2 splits it in space: order[k] is the index of the k-th centre.
std::vector<uint32_t> median_split_order(const std::vector<Vec3>& centres);

}  // namespace geodesic
