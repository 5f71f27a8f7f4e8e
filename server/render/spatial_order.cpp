#include "render/spatial_order.h"

#include <algorithm>
#include <numeric>

namespace geodesic {
namespace {

// Orders order[first..last] (inclusive, as the driver's build counts them).
void split(const std::vector<Vec3>& centres, std::vector<uint32_t>& order, size_t first,
           size_t last) {
  if (last <= first) return;
  Vec3 lo = centres[order[first]], hi = lo;
  for (size_t i = first; i <= last; ++i) {
    const Vec3& c = centres[order[i]];
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
    hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
  }
  const Vec3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const size_t middle = (first + last) / 2;
  std::nth_element(order.begin() + long(first), order.begin() + long(middle),
                   order.begin() + long(last) + 1,
                   [&](uint32_t a, uint32_t b) { return centres[a][axis] < centres[b][axis]; });
  split(centres, order, first, middle);
  split(centres, order, middle + 1, last);
}

}  // namespace

std::vector<uint32_t> median_split_order(const std::vector<Vec3>& centres) {
  std::vector<uint32_t> order(centres.size());
  std::iota(order.begin(), order.end(), 0u);
  if (!order.empty()) split(centres, order, 0, order.size() - 1);
  return order;
}

}  // namespace geodesic
