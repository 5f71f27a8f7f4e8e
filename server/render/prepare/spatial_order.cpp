#include "render/prepare/spatial_order.h"

#include <algorithm>
#include <array>
#include <numeric>

namespace geodesic {
namespace {

using Order = std::vector<uint32_t>;

// Surface area of the box around boxes[order[first..last]].
double area(const std::vector<PrimitiveBox>& boxes, const uint32_t* order, size_t count) {
  Vec3 lo = boxes[order[0]].lo, hi = boxes[order[0]].hi;
  for (size_t i = 1; i < count; ++i) {
    const PrimitiveBox& b = boxes[order[i]];
    lo = {std::min(lo.x, b.lo.x), std::min(lo.y, b.lo.y), std::min(lo.z, b.lo.z)};
    hi = {std::max(hi.x, b.hi.x), std::max(hi.y, b.hi.y), std::max(hi.z, b.hi.z)};
  }
  const Vec3 e = hi - lo;
  return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

// The SAH cost of halving order[first..last] (inclusive, as the driver counts) at its middle.
double halving_cost(const std::vector<PrimitiveBox>& boxes, const uint32_t* range, size_t count) {
  const size_t left = count / 2 + count % 2;  // [first, (first + last) / 2]
  return area(boxes, range, left) * double(left) +
         area(boxes, range + left, count - left) * double(count - left);
}

void split(const std::vector<PrimitiveBox>& boxes, Order& order, size_t first, size_t last) {
  if (last <= first) return;
  const size_t count = last - first + 1, middle = (first + last) / 2;
  const auto begin = order.begin() + long(first), end = order.begin() + long(last) + 1;
  // Four candidates: as it came, then at the median along each axis of the boxes' centres.
  Order best(begin, end);
  double best_cost = halving_cost(boxes, best.data(), count);
  for (int axis = 0; axis < 3; ++axis) {
    Order candidate(begin, end);
    std::nth_element(candidate.begin(), candidate.begin() + long(middle - first), candidate.end(),
                     [&](uint32_t a, uint32_t b) {
                       return boxes[a].lo[axis] + boxes[a].hi[axis] < boxes[b].lo[axis] + boxes[b].hi[axis];
                     });
    const double cost = halving_cost(boxes, candidate.data(), count);
    if (cost < best_cost) {
      best_cost = cost;
      best = std::move(candidate);
    }
  }
  std::copy(best.begin(), best.end(), begin);
  split(boxes, order, first, middle);
  split(boxes, order, middle + 1, last);
}

double tree_cost(const std::vector<PrimitiveBox>& boxes, const Order& order, size_t first, size_t last) {
  if (last <= first) return 0;
  const size_t middle = (first + last) / 2;
  return halving_cost(boxes, order.data() + first, last - first + 1) +
         tree_cost(boxes, order, first, middle) + tree_cost(boxes, order, middle + 1, last);
}

}  // namespace

std::vector<uint32_t> index_split_order(const std::vector<PrimitiveBox>& boxes) {
  Order order(boxes.size());
  std::iota(order.begin(), order.end(), 0u);
  if (!order.empty()) split(boxes, order, 0, order.size() - 1);
  return order;
}

double index_split_cost(const std::vector<PrimitiveBox>& boxes, const std::vector<uint32_t>& order) {
  return order.empty() ? 0 : tree_cost(boxes, order, 0, order.size() - 1);
}

}  // namespace geodesic
