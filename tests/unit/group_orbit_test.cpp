// GroupOrbit::find, which tells a newly enumerated element from one already known by its image
// of the origin: every point within the tolerance (1e-7 of the point's size) of a known image is
// that element, wherever the two fall in the hash grid, and a point a few tolerances away is
// none. The integer lattice of E3 puts its images on many cells' sides at once; in H3 the
// mirrored right-angled dodecahedron's images go out to coordinates of about 27, and the powers
// of one long translation to cosh(240), beyond any integer grid of absolute cells.
#include "scene/group_orbit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scene/manifold.h"

namespace geodesic {
namespace {

double tolerance_at(const Vec4& p) {
  return 1e-7 * std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z), std::abs(p.w)});
}

Vec4 shifted(const Vec4& p, int signs, double by) {
  Vec4 q = p;
  double* c[4] = {&q.x, &q.y, &q.z, &q.w};
  for (int i = 0; i < 4; ++i) *c[i] += (signs >> i & 1 ? by : -by);
  return q;
}

void expect_found_across_cell_sides(const GroupOrbit& orbit) {
  for (std::size_t i = 0; i < orbit.elements().size(); ++i) {
    const Vec4& p = orbit.elements()[i].point;
    const double tolerance = tolerance_at(p);
    ASSERT_EQ(orbit.find(p), int(i));
    for (int signs = 0; signs < 16; ++signs) {
      // Within the tolerance on every axis at once (max-norm), on either side of each.
      EXPECT_EQ(orbit.find(shifted(p, signs, 0.45 * tolerance)), int(i)) << i << " " << signs;
      EXPECT_EQ(orbit.find(shifted(p, signs, 3 * tolerance)), -1) << i << " " << signs;
    }
  }
}

TEST(GroupOrbit, FindsAnImageOfTheOriginFromEverySideOfItsGridCell) {
  // Z3 within 2.5: the 81 lattice points (x, y, z, 1), each on a corner of its grid cell.
  std::vector<Mat4> generators;
  for (const Vec3& axis : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}})
    generators.push_back(model::translation(GeometryKind::Euclidean, axis));
  const GroupOrbit orbit(GeometryKind::Euclidean, generators, 100000, 2.5);
  ASSERT_EQ(orbit.elements().size(), 81u);
  expect_found_across_cell_sides(orbit);
}

TEST(GroupOrbit, FindsImagesFarOutInH3) {
  // The reflections in the right-angled dodecahedron's faces, images out to distance 4.
  std::vector<Mat4> generators;
  for (const auto& face : make_mirrored_dodecahedron().faces) generators.push_back(face.pairing);
  const GroupOrbit orbit(GeometryKind::Hyperbolic, generators, 200000, 4.0);
  ASSERT_GT(orbit.elements().size(), 1000u);
  double farthest = 0;
  for (const GroupElement& e : orbit.elements()) farthest = std::max(farthest, e.point.w);
  EXPECT_GT(farthest, 20.0);
  expect_found_across_cell_sides(orbit);
}

TEST(GroupOrbit, EnumeratesFarBeyondTheRangeOfAnyIntegerGrid) {
  // Long translations out to distances where coordinates reach cosh(240) ~ 1e104 or overflow
  // (generator text with entries near 1e17 went there). Double precision no longer tells the
  // elements apart so far out (dirichlet_domain enumerates H3 only within distance 10), so
  // what is found varies, but the enumeration stays well defined: it ends with finite images
  // only, each found again from every side of its grid cell, or it reports a fixed point or
// too many elements.
  const auto kH3 = GeometryKind::Hyperbolic;
  int enumerated = 0;
  for (double step : {20.0, 40.0, 300.0})
    for (double limit : {5 * step + 5, 1e6}) {
      try {
        const GroupOrbit orbit(kH3, {model::translation(kH3, Vec3{step, 0, 0})}, 1000, limit);
        ++enumerated;
        EXPECT_FALSE(orbit.complete()) << step << " " << limit;
        ASSERT_GE(orbit.elements().size(), 3u) << step << " " << limit;
        for (const GroupElement& e : orbit.elements()) {
          for (double x : {e.point.x, e.point.y, e.point.z, e.point.w})
            EXPECT_TRUE(std::isfinite(x)) << step << " " << limit;
          EXPECT_LE(e.displacement, limit);
        }
        expect_found_across_cell_sides(orbit);
      } catch (const GroupOrbit::Stabilised&) {
      } catch (const GroupOrbit::TooLarge&) {
      }
    }
  EXPECT_GT(enumerated, 0);
  const GroupOrbit near(kH3, {model::translation(kH3, Vec3{1, 0, 0})}, 1000, 5.5);
  EXPECT_EQ(near.elements().size(), 11u);
  EXPECT_EQ(near.find(Vec4{NAN, 0, 0, 1}), -1);
  EXPECT_EQ(near.find(Vec4{0, NAN, 0, NAN}), -1);
  EXPECT_EQ(near.find(Vec4{0, 0, 0, INFINITY}), -1);
}

}  // namespace
}  // namespace geodesic
