#include "scene/group_orbit.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "scene/preparation_budget.h"

namespace geodesic {
namespace {

// Origin images closer than this (relative to their size) are the same point. Distinct orbit
// points of a discrete group lie at least twice the Dirichlet domain's in-radius apart, many
// orders of magnitude more; one re-orthonormalised product errs by about 1e-15.
constexpr double kSamePoint = 1e-7;
// The hash grid is laid over a point's coordinates divided by its size (size_of), which lie in
// [-1, 1] however far the point is (cosh of the displacement in H3 overflows any integer grid
// of absolute cells far out). A point q within kSamePoint * Sp of the point p looked up (Sp, Sq
// their sizes) differs there by less than 2 kSamePoint: p/Sp - q/Sq = (p - q)/Sp +
// (q/Sq)(Sq - Sp)/Sp, |q/Sq| <= 1, and size_of is 1-Lipschitz in the max-norm.
constexpr double kCell = 1e-5;                   // grid spacing, coarser than that reach
constexpr double kReach = 2.5 * kSamePoint;      // that reach, with room for rounding

double max_abs_difference(const Mat4& a, const Mat4& b) {
  double m = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m = std::max(m, std::abs(a.m[i][j] - b.m[i][j]));
  return m;
}

double coordinate_distance(const Vec4& a, const Vec4& b) {
  return max_abs(a - b);
}

double size_of(const Vec4& p) {
  return std::max(1.0, max_abs(p));
}

// Products between two looks at the preparation budget (about a millisecond of work).
constexpr unsigned kBudgetStride = 4096;
// Nielsen moves stop after this many rounds over the generators: the result is the same group
// whenever they stop.
constexpr int kMaxReductionRounds = 64;
constexpr unsigned kMaxReductionProducts = 1u << 24;

struct Shortened {
  Mat4 g;
  double length;
};

bool finite(const Vec4& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

// The point's coordinates in grid cells: within +-1 / kCell.
std::array<double, 4> grid_coordinates(const Vec4& p) {
  const double size = size_of(p);
  return {p.x / size / kCell, p.y / size / kCell, p.z / size / kCell, p.w / size / kCell};
}

}  // namespace

double displacement(GeometryKind kind, const Vec4& p) {
  return model::geodesic_distance(kind, model::origin(), p);
}

std::vector<Mat4> reduce_generators(GeometryKind kind, const std::vector<Mat4>& generators) {
  const auto length_of = [&](const Mat4& g) { return displacement(kind, g * model::origin()); };
  const auto is_identity = [](const Mat4& g) {
    return max_abs_difference(g, Mat4::identity()) < 1e-9;
  };
  std::vector<Shortened> set;
  for (const Mat4& g : generators)
    if (!is_identity(g)) set.push_back({model::reorthonormalize(kind, g), length_of(g)});
  unsigned products = 0;
  bool changed = true;
  for (int round = 0; changed && round < kMaxReductionRounds; ++round) {
    changed = false;
    std::stable_sort(set.begin(), set.end(),
                     [](const Shortened& a, const Shortened& b) { return a.length < b.length; });
    for (std::size_t i = 1; i < set.size(); ++i) {
      for (std::size_t j = 0; j < i && !is_identity(set[i].g); ++j) {
        if (is_identity(set[j].g)) continue;
        const Mat4 inverse = model::inverse_isometry(kind, set[j].g);
        for (bool shorter = true; shorter && products < kMaxReductionProducts;) {
          shorter = false;
          if (++products % kBudgetStride == 0) check_preparation_budget();
          for (const Mat4& h : {set[j].g, inverse}) {
            const Mat4 product = model::reorthonormalize(kind, set[i].g * h);
            const double length = length_of(product);
            // Strictly shorter by more than round-off: the moves end.
            if (length < set[i].length - 1e-9 * std::max(1.0, set[i].length)) {
              set[i] = {product, length};
              changed = true;
              shorter = !is_identity(product);
              break;
            }
          }
        }
      }
    }
    std::erase_if(set, [&](const Shortened& s) { return is_identity(s.g); });
  }
  std::vector<Mat4> result;
  for (const Shortened& s : set) result.push_back(s.g);
  return result;
}

GroupOrbit::GroupOrbit(GeometryKind kind, const std::vector<Mat4>& generators,
                       std::size_t max_elements, double limit)
    : kind_(kind), max_elements_(max_elements) {
  for (const Mat4& g : generators)
    for (const Mat4& h : {g, model::inverse_isometry(kind, g)})
      generators_.push_back(model::reorthonormalize(kind, h));
  add(Mat4::identity(), limit);
  // Breadth first: elements_ grows while it is scanned.
  unsigned products = 0;
  for (std::size_t next = 0; next < elements_.size(); ++next)
    for (const Mat4& h : generators_) {
      if (++products % kBudgetStride == 0) check_preparation_budget();
      const Mat4 product = elements_[next].g * h;
      // Relative: the form's round-off grows with |g|^2 (cosh^2 of the displacement in H3).
      const double size = size_of(product * model::origin());
      drift_ = std::max(drift_, model::isometry_error(kind_, product) / (size * size));
      add(model::reorthonormalize(kind_, product), limit);
    }
}

GroupOrbit::Key GroupOrbit::key(const Vec4& p, int corner) const {
  const std::array<double, 4> x = grid_coordinates(p);
  Key k = 0;
  for (int i = 0; i < 4; ++i) {
    const double s = x[i];
    long long q = static_cast<long long>(std::floor(s));
    // Corner bit i: also look in the neighbouring cell nearest to the point.
    if (corner >> i & 1) q += s - std::floor(s) < 0.5 ? -1 : 1;
    k = k * 1000003 + static_cast<Key>(q);
  }
  return k;
}

int GroupOrbit::find(const Vec4& point) const {
  if (!finite(point)) return -1;  // every known image is finite
  const double tolerance = kSamePoint * size_of(point);
  // A point within `tolerance` of this one lies in the next grid cell along axis i only if
  // this one lies within kReach of the side of its cell: look there alone (usually one cell,
  // not 16).
  const std::array<double, 4> x = grid_coordinates(point);
  int near_sides = 0;
  for (int i = 0; i < 4; ++i) {
    const double f = x[i] - std::floor(x[i]);
    if (std::min(f, 1 - f) * kCell < kReach) near_sides |= 1 << i;
  }
  for (int corner = 0; corner < 16; ++corner) {
    if (corner & ~near_sides) continue;
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
  if (!(d <= limit) || !finite(point)) {  // also a product that overflowed
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
