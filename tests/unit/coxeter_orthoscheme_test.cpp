// The compact hyperbolic Coxeter orthoschemes: their reflections and Lobachevsky's volume
// formula, held to identities and to published volumes of the dodecahedral spaces they tile.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/catalogue.h"
#include "scene/coxeter_orthoscheme.h"
#include "scene/scene.h"
#include "test_constants.h"

namespace geodesic {
namespace {

using test::kPi;

TEST(Lobachevsky, OddPeriodicAndDuplicating) {
  for (double x : {0.1, 0.4, 0.7, 1.0, 1.3}) {
    EXPECT_NEAR(lobachevsky(-x), -lobachevsky(x), 1e-13) << x;
    EXPECT_NEAR(lobachevsky(x + kPi), lobachevsky(x), 1e-12) << x;
    // L(2x) = 2 L(x) + 2 L(x + pi/2)
    EXPECT_NEAR(lobachevsky(2 * x), 2 * lobachevsky(x) + 2 * lobachevsky(x + kPi / 2), 1e-11) << x;
  }
  EXPECT_NEAR(lobachevsky(kPi / 2), 0, 1e-13);
  EXPECT_NEAR(lobachevsky(kPi / 6), 1.5 * lobachevsky(kPi / 3), 1e-12);  // L(3x) = 3 sum L(x + k pi/3)
}

// 120 orthoschemes [5,3,4] make the right-angled dodecahedron and 120 of [5,3,5] the one with
// 72-degree angles: volumes 4.306207601 (Vesnin) and 11.199064740 (Weeks, SnapPea census).
TEST(CoxeterOrthoscheme, VolumesTileTheDodecahedralSpaces) {
  EXPECT_NEAR(120 * orthoscheme_volume(5, 3, 4), 4.306207601, 2e-9);
  EXPECT_NEAR(120 * orthoscheme_volume(5, 3, 5), 11.199064740, 2e-9);
  EXPECT_NEAR(orthoscheme_volume(4, 3, 5), orthoscheme_volume(5, 3, 4), 1e-14);  // the same simplex
  EXPECT_NEAR(orthoscheme_volume(3, 5, 3), 0.0390502856, 1e-10);  // the smallest (Johnson et al. 1999)
}

// Four reflections of O(3,1) whose products of pairs have the diagram's orders.
TEST(CoxeterOrthoscheme, ReflectionsObeyTheDiagram) {
  const std::vector<Mat4> r = coxeter_orthoscheme_generators(5, 3, 4);
  ASSERT_EQ(r.size(), 4u);
  const int order[4][4] = {{1, 5, 2, 2}, {5, 1, 3, 2}, {2, 3, 1, 4}, {2, 2, 4, 1}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Mat4 power = Mat4::identity();
      const Mat4 step = r[i] * r[j];
      for (int k = 0; k < order[i][j]; ++k) power = power * step;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) EXPECT_NEAR(power.m[a][b], a == b, 1e-12) << i << j;
      EXPECT_LT(model::isometry_error(GeometryKind::Hyperbolic, r[i]), 1e-14);
    }
}

TEST(CoxeterOrthoscheme, RefusesDiagramsThatAreNotCompactHyperbolic) {
  auto error = [](int p, int q, int r) {
    try {
      coxeter_orthoscheme_generators(p, q, r);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error(3, 3, 3).find("not hyperbolic"), std::string::npos) << error(3, 3, 3);  // the 4-simplex
  EXPECT_NE(error(4, 3, 4).find("not hyperbolic"), std::string::npos) << error(4, 3, 4);  // cubic honeycomb
  EXPECT_NE(error(3, 6, 3).find("ideal"), std::string::npos) << error(3, 6, 3);
  EXPECT_NE(error(2, 3, 5).find("ideal"), std::string::npos) << error(2, 3, 5);
}

}  // namespace
}  // namespace geodesic
