// The elements of a discrete group Gamma of isometries that move the origin by at most a limit,
// enumerated breadth-first over words in the generators and their inverses whose every prefix
// stays within the limit, each identified by its image of the origin. That identification
// needs the origin to have a trivial stabiliser; an element that fixes it is reported instead
// (Stabilised).
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "geometry/model.h"
#include "geometry/vec.h"

namespace geodesic {

struct GroupElement {
  Mat4 g;                // re-orthonormalised product of a shortest word found
  Vec4 point;            // g applied to the origin
  double displacement;   // d(origin, g origin)
};

class GroupOrbit {
 public:
  struct Stabilised {};  // thrown: some element other than the identity fixes the origin
  struct TooLarge {};    // thrown: more than max_elements elements

  // Enumerates every element reachable through elements of displacement <= limit: all those
  // within limit - slack when words for them exist whose prefixes stray at most `slack`
  // beyond them (the domain's circumradius, for face pairings).
  GroupOrbit(GeometryKind kind, const std::vector<Mat4>& generators, std::size_t max_elements,
             double limit);

  // True when no element lay beyond the limit: the group is finite and fully enumerated.
  bool complete() const { return !beyond_; }

  const std::vector<GroupElement>& elements() const { return elements_; }  // [0]: identity
  // The element whose origin image is `point`, or -1.
  int find(const Vec4& point) const;
  // Largest isometry_error / |g|^2 of a product before it was re-orthonormalised.
  double product_drift() const { return drift_; }

 private:
  using Key = std::uint64_t;  // unsigned: the hash wraps around (signed overflow is undefined)
  Key key(const Vec4& p, int corner) const;
  void add(const Mat4& g, double limit);

  GeometryKind kind_;
  std::vector<Mat4> generators_;  // with inverses, re-orthonormalised
  std::size_t max_elements_;
  double drift_ = 0;
  bool beyond_ = false;
  std::vector<GroupElement> elements_;
  std::unordered_map<Key, std::vector<int>> grid_;
};

// Generators of the same group, shortened: each is replaced by its product with a shorter one
// (or that one's inverse) while that moves the origin less, and those that become the identity
// are dropped (Nielsen moves, which keep the group). Redundant or nearly parallel generators
// (200 translations by 2, 2.001, 2.002, ...) otherwise multiply the enumeration's work by their
// count and its ball by their lengths over the group's real step.
std::vector<Mat4> reduce_generators(GeometryKind kind, const std::vector<Mat4>& generators);

// d(origin, p) in the model.
double displacement(GeometryKind kind, const Vec4& p);

}  // namespace geodesic
