#include "scene/group_orbit.h"

#include <algorithm>
#include <cmath>

namespace geodesic {
namespace {

// Origin images closer than this (relative to their size) are the same point. Distinct orbit
// points of a discrete group lie at least twice the Dirichlet domain's in-radius apart, many
// orders of magnitude more; one re-orthonormalised product errs by about 1e-15.
constexpr double kSamePoint = 1e-7;
constexpr double kCell = 1e-4;  // hash grid spacing, coarser than kSamePoint

double max_abs_difference(const Mat4& a, const Mat4& b) {
  double m = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m = std::max(m, std::abs(a.m[i][j] - b.m[i][j]));
  return m;
}

double coordinate_distance(const Vec4& a, const Vec4& b) {
  return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z),
                   std::abs(a.w - b.w)});
}

double size_of(const Vec4& p) {
  return std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z), std::abs(p.w)});
}

}  // namespace

double displacement(GeometryKind kind, const Vec4& p) {
  return model::geodesic_distance(kind, model::origin(), p);
}

GroupOrbit::GroupOrbit(GeometryKind kind, const std::vector<Mat4>& generators,
                       std::size_t max_elements, double limit)
    : kind_(kind), max_elements_(max_elements) {
  for (const Mat4& g : generators)
    for (const Mat4& h : {g, model::inverse_isometry(kind, g)})
      generators_.push_back(model::reorthonormalize(kind, h));
  add(Mat4::identity(), limit);
  // Breadth first: elements_ grows while it is scanned.
  for (std::size_t next = 0; next < elements_.size(); ++next)
    for (const Mat4& h : generators_) {
      const Mat4 product = elements_[next].g * h;
      // Relative: the form's round-off grows with |g|^2 (cosh^2 of the displacement in H3).
      const double size = size_of(product * model::origin());
      drift_ = std::max(drift_, model::isometry_error(kind_, product) / (size * size));
      add(model::reorthonormalize(kind_, product), limit);
    }
}

GroupOrbit::Key GroupOrbit::key(const Vec4& p, int corner) const {
  const double x[4] = {p.x, p.y, p.z, p.w};
  Key k = 0;
  for (int i = 0; i < 4; ++i) {
    const double s = x[i] / kCell;
    long long q = static_cast<long long>(std::floor(s));
    // Corner bit i: also look in the neighbouring cell nearest to the point.
    if (corner >> i & 1) q += s - std::floor(s) < 0.5 ? -1 : 1;
    k = k * 1000003 + static_cast<Key>(q);
  }
  return k;
}

int GroupOrbit::find(const Vec4& point) const {
  const double tolerance = kSamePoint * size_of(point);
  for (int corner = 0; corner < 16; ++corner) {
    const auto it = grid_.find(key(point, corner));
    if (it == grid_.end()) continue;
    for (int i : it->second)
      if (coordinate_distance(elements_[i].point, point) < tolerance) return i;
  }
  return -1;
}

void GroupOrbit::add(const Mat4& g, double limit) {
  const Vec4 point = g * model::origin();
  const double d = displacement(kind_, point);
  if (d > limit) {
    beyond_ = true;
    return;
  }
  const int known = find(point);
  if (known >= 0) {
    // Two elements with one image of the origin: their quotient fixes it.
    if (max_abs_difference(elements_[known].g, g) > 1e-6 * size_of(point)) throw Stabilised{};
    return;
  }
  if (elements_.size() >= max_elements_) throw TooLarge{};
  const int index = static_cast<int>(elements_.size());
  elements_.push_back({g, point, d});
  grid_[key(point, 0)].push_back(index);
}

}  // namespace geodesic
