// Primitives in the order of a good tree over their boxes. Some drivers build a bottom-level
// acceleration structure by splitting the primitive list at its middle index, without looking
// at positions (Mesa lavapipe: lvp_build_internal_node halves [first, last] at (first + last)
// / 2), so the tree is only as good as the order it is given: boxes listed mesh by mesh, or
// tubes edge by edge, give nodes whose boxes span the whole scene, and every traversal visits
// most of them. Listed in this order, that driver's index split is the best of four at every
// node by the surface area heuristic (SAH: the halves' box areas times their primitive
// counts): the range as it came, or sorted at its median along x, y or z. A driver with a
// builder of its own is unaffected.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/vec.h"

namespace geodesic {

struct PrimitiveBox {
  Vec3 lo, hi;
};

// The permutation that lists `boxes` so that halving every index range [first, last] at
// (first + last) / 2 is the split chosen above: order[k] is the index of the k-th box.
std::vector<uint32_t> index_split_order(const std::vector<PrimitiveBox>& boxes);

// The SAH cost of the tree that halving index ranges builds over `boxes` listed in `order`:
// the sum over its inner nodes of their children's box areas times their primitive counts.
double index_split_cost(const std::vector<PrimitiveBox>& boxes, const std::vector<uint32_t>& order);

}  // namespace geodesic
