// Cusped hyperbolic manifolds: Moebius generators (geometry/moebius.h, scene/moebius_text.h),
// Dirichlet domains with ideal vertices and their volumes, cusps and their horoball
// neighbourhoods (scene/cusp_neighbourhoods.h), and groups of infinite volume refused.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <string>

#include "geometry/moebius.h"
#include "scene/catalogue.h"
#include "scene/cusp_neighbourhoods.h"
#include "scene/dirichlet_domain.h"
#include "scene/generator_file.h"
#include "scene/moebius_text.h"
#include "scene/scene.h"
#include "test_constants.h"

namespace geodesic {
namespace {

using test::kH3;
using test::max_difference;
const Complex kOmega(-0.5, std::sqrt(3.0) / 2);

// The boundary point a null vector is aimed at.
Complex boundary_of(const Vec4& x) {
  // (zeta, 1)(zeta, 1)^*: w + z = |zeta|^2 s, w - z = s, x + i y = zeta s.
  return Complex(x.x, x.y) / (x.w - x.z);
}

TEST(Moebius, IsAHomomorphismActingOnTheBoundaryAsZToAzPlusBOverCzPlusD) {
  const Moebius a{{1, Complex(0.3, -2), Complex(0.1, 0.2), 1}, false};
  const Moebius b{{Complex(0, 1), 2, Complex(-0.5, 0.5), Complex(3, -1)}, false};
  Moebius ab{{a.abcd[0] * b.abcd[0] + a.abcd[1] * b.abcd[2], a.abcd[0] * b.abcd[1] + a.abcd[1] * b.abcd[3],
              a.abcd[2] * b.abcd[0] + a.abcd[3] * b.abcd[2], a.abcd[2] * b.abcd[1] + a.abcd[3] * b.abcd[3]},
             false};
  const Mat4 ga = moebius_isometry(a), gb = moebius_isometry(b);
  EXPECT_LT(model::isometry_error(kH3, ga), 1e-12);
  EXPECT_LT(model::isometry_error(kH3, gb), 1e-12);
  EXPECT_LT(max_difference(ga * gb, moebius_isometry(ab)), 1e-11);
  for (const Complex z : {Complex(0, 0), Complex(0.7, -1.3), Complex(-4, 2)}) {
    const Complex expected = (a.abcd[0] * z + a.abcd[1]) / (a.abcd[2] * z + a.abcd[3]);
    EXPECT_LT(std::abs(boundary_of(ga * boundary_point(z)) - expected), 1e-12) << z;
    // Orientation-reversing: z -> (a conj z + b) / (c conj z + d).
    const Moebius r{a.abcd, true};
    const Complex reflected =
        (a.abcd[0] * std::conj(z) + a.abcd[1]) / (a.abcd[2] * std::conj(z) + a.abcd[3]);
    EXPECT_LT(std::abs(boundary_of(moebius_isometry(r) * boundary_point(z)) - reflected), 1e-12);
  }
  // z -> z + 1 fixes infinity (the north pole), and -A is the same isometry as A.
  const Mat4 shift = moebius_isometry({{1, 1, 0, 1}, false});
  const Vec4 north = shift * boundary_infinity();
  EXPECT_LT(length(north.xyz() / north.w - Vec3{0, 0, 1}), 1e-15);
  EXPECT_LT(max_difference(shift, moebius_isometry({{-1, -1, 0, -1}, false})), 1e-15);
}

TEST(MoebiusText, ReadsSnapPyAndPythonNotation) {
  // SnapPy's SL2C printout (rows in brackets, "*I"), Python's complex literals, conj.
  const std::string text =
      "# Figure-eight knot complement\n"
      "[1.00000000000000  1.00000000000000]\n"
      "[0  1.00000000000000]\n"
      "\n"
      "[ 1  0 ]\n"
      "[ 0.5 - 0.86602540378443865*I   1.0000000000000000 + 1.2E-17*I ]\n"
      "[[(1+0j), 2j], [-1j, (1-2j)]]\n"
      "conj [[0, 1], [-1, 0]]\n";
  ASSERT_TRUE(looks_like_moebius(text));
  const std::vector<MoebiusText> m = read_moebius(text, "m004.txt");
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[1].t.abcd[2], Complex(0.5, -0.86602540378443865));
  EXPECT_NEAR(m[1].t.abcd[3].imag(), 1.2e-17, 1e-30);
  EXPECT_EQ(m[1].line, 5);
  EXPECT_EQ(m[2].t.abcd[1], Complex(0, 2));
  EXPECT_EQ(m[2].t.abcd[3], Complex(1, -2));
  EXPECT_FALSE(m[2].t.reverses);
  EXPECT_TRUE(m[3].t.reverses);
  // "a -b*I" (a space before the sign only) is two entries: here 5, not a multiple of 4.
  EXPECT_THROW(read_moebius("[1 -1*I] [0 1] [2]", "x"), SceneError);
  const GeneratorSet set = parse_generators(text, "m004.txt");
  EXPECT_EQ(set.kind, kH3);
  EXPECT_EQ(set.title, "Figure-eight knot complement");
  // O(3,1) rows of four are still SnapPy's pairing matrices.
  EXPECT_FALSE(looks_like_moebius("[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]"));
}

TEST(MoebiusText, ErrorsNameMatrixLineAndReason) {
  auto message = [](const std::string& text) {
    try {
      parse_generators(text, "g.txt");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("[[1, 1], [0, 1]]\n[[1, 2], [2, 4]]"),
            "g.txt: matrix 2 (line 2): determinant ad - bc is 0: not a Moebius transformation");
  EXPECT_EQ(message("[[1, 1], [0, 1]]\n[[1, 2], [3]]"),
            "g.txt: matrix 2 (line 2): row 2, [3], has 1 entry, not 2");
  EXPECT_EQ(message("[[1, 1], [0, 1 2]]"), "g.txt: matrix 1 (line 1): row 2, [0, 1 2], has 3 entries, not 2");
  // Rows without brackets are counted as a whole.
  EXPECT_EQ(message("[[1, 1], [0, 1]]\n[[1, 2] [3 (4 + 1j) 5]]"),
            "g.txt: matrix 2 (line 2): row 2, [3 (4 + 1j) 5], has 3 entries, not 2");
  EXPECT_NE(message("[[1, 1], [0, 1e999]]").find("is not a finite number"), std::string::npos);
}

// Figure-eight (m004) and Whitehead link: volume to 1e-9, ideal vertices, cusps, pairings
// exact to 1e-12 (validated at that tolerance), acting freely, and completeness.
TEST(CuspedDomains, VolumesCuspsAndExactPairings) {
  const struct {
    const char* name;
    double volume;
    int cusps;
  } kCases[] = {{"figure-eight", 2.029883212819307, 1},
                {"figure-eight-sister", 2.029883212819307, 1},
                {"gieseking", 1.0149416064096536, 1},
                {"whitehead-link", 3.663862376708876, 2}};
  for (const auto& c : kCases) {
    SCOPED_TRACE(c.name);
    const CatalogueEntry& e = *find_catalogue_entry(c.name);
    const DirichletDomain d = dirichlet_domain(e.kind, e.generators);
    EXPECT_NEAR(d.volume, c.volume, 1e-9);
    EXPECT_EQ(d.cusps, c.cusps);
    EXPECT_NO_THROW(validate_manifold(kH3, d.manifold, 1e-12));
    int ideal = 0;
    for (const Vec3& v : d.manifold.domain.vertices) ideal += ideal_vertex(kH3, v);
    EXPECT_GE(ideal, c.cusps);
    for (const EdgeCycle& cycle : edge_cycles(kH3, d.manifold)) EXPECT_EQ(cycle.order, 1);
    // The horoballs: one per ideal vertex, consistent round each cusp (no throw), disjoint
    // from each other's images, and the origin outside them.
    const auto horospheres = cusp_horospheres(d.manifold);
    EXPECT_EQ(static_cast<int>(horospheres.size()), ideal);
    std::vector<Mat4> words{Mat4::identity()};
    for (const DomainFace& f : d.manifold.faces)
      for (const DomainFace& g : d.manifold.faces) words.push_back(f.pairing * g.pairing);
    for (const CuspHorosphere& h : horospheres) {
      EXPECT_GE(h.distance, 0.5 - 1e-12);  // the default clearance from the origin
      EXPECT_LT(h.distance, 30);
      EXPECT_NEAR(length(h.direction), 1, 1e-12);
      const Vec4 l = std::exp(h.distance) * Vec4(h.direction, 1);
      for (const CuspHorosphere& other : horospheres)
        for (const Mat4& w : words) {  // horoballs {<x, l> > -1} disjoint: <l, l'> <= -2
          const Vec4 image = w * (std::exp(other.distance) * Vec4(other.direction, 1));
          if (length(image.xyz() / image.w - h.direction) < 1e-6) continue;  // the same cusp point
          EXPECT_LE(model::inner(kH3, l, image), -2 + 1e-9);
        }
    }
    // The same group seen from a generic base point: another domain (one ideal vertex per cusp
    // instead of the symmetric point's two for the figure-eight, whose cell then needs 7701
    // elements, products to distance 8 that carry 1e-8 of round-off into its vertices).
    DirichletOptions moved;
    moved.base_point = Vec3{0.11, -0.07, 0.05};
    EXPECT_NEAR(dirichlet_domain(e.kind, e.generators, moved).volume, c.volume, 5e-8);
  }
}

// The area of a cusp's horosphere within the domain, summed over the cusp's ideal vertices: the
// cusp torus' (Klein bottle's) cross-section. Grown until two horoballs touch (no margin, no
// clearance) it is the maximal cusp, whose area is known: 2 sqrt 3 for the figure-eight knot
// complement and its sister (cusp volume sqrt 3, area twice the volume), sqrt 3 for the
// Gieseking manifold, which the figure-eight double covers. Moving a horosphere s deeper
// scales its area by e^-2s (the horosphere is flat, and distances along it shrink by e^-s);
// without faces through its ideal point it has no bounded share of the domain.
TEST(CuspedDomains, MaximalCuspAreas) {
  const struct {
    const char* name;
    double area;
  } kCases[] = {{"figure-eight", 2 * std::sqrt(3.0)},
                {"figure-eight-sister", 2 * std::sqrt(3.0)},
                {"gieseking", std::sqrt(3.0)}};
  for (const auto& c : kCases) {
    SCOPED_TRACE(c.name);
    const CatalogueEntry& e = *find_catalogue_entry(c.name);
    const DirichletDomain d = dirichlet_domain(e.kind, e.generators);
    double area = 0, deeper = 0;
    for (const CuspHorosphere& h : cusp_horospheres(d.manifold, 0, -INFINITY)) {
      area += horosphere_area_in_domain(d.manifold, std::exp(h.distance) * Vec4(h.direction, 1));
      deeper += horosphere_area_in_domain(d.manifold,
                                          std::exp(h.distance + 0.7) * Vec4(h.direction, 1));
    }
    EXPECT_NEAR(area, c.area, 1e-9);
    EXPECT_NEAR(deeper, c.area * std::exp(-1.4), 1e-9);
  }
  const DirichletDomain d =
      dirichlet_domain(kH3, find_catalogue_entry("figure-eight")->generators);
  EXPECT_EQ(horosphere_area_in_domain(d.manifold, std::exp(1.0) * Vec4(0.6, 0, 0.8, 1)), INFINITY);
}

// The catalogue's generators satisfy their groups' presentations (a word left to right is the
// product of its letters' matrices; capitals are inverses), to round-off.
TEST(CuspedDomains, GeneratorsSatisfyTheirRelators) {
  const struct {
    const char* name;
    const char* relator;
  } kCases[] = {{"figure-eight", "abABaBAbaB"},   // a w = w b, w = b a^-1 b^-1 a (Riley)
                {"figure-eight-sister", "BaaBBBaaBa"},
                {"gieseking", "aabbAB"},          // a^2 b^2 = b a
                {"whitehead-link", "abaBABabABAbabAB"}};  // a w = w a, w = b a B A B a b
  for (const auto& c : kCases) {
    SCOPED_TRACE(c.name);
    const CatalogueEntry& e = *find_catalogue_entry(c.name);
    ASSERT_EQ(e.generators.size(), 2u);
    Mat4 product = Mat4::identity();
    for (const char* letter = c.relator; *letter; ++letter) {
      const Mat4& g = e.generators[std::tolower(*letter) - 'a'];
      product = product * (std::isupper(*letter) ? model::inverse_isometry(kH3, g) : g);
    }
    EXPECT_LT(max_difference(product, Mat4::identity()), 1e-11);
  }
}

// Riley's generators typed as SnapPy prints them give the catalogue's figure-eight.
TEST(CuspedDomains, FromMoebiusText) {
  const GeneratorSet set = parse_generators(
      "[1  1]\n[0  1]\n\n[1  0]\n[0.5 - 0.8660254037844386*I  1]\n", "m004.txt");
  const DirichletDomain d = dirichlet_domain(set.kind, set.generators);
  EXPECT_NEAR(d.volume, 2.029883212819307, 1e-9);
  EXPECT_EQ(d.cusps, 1);
}

// A parabolic group (one translation, or a lattice of them, fixing infinity) is discrete but
// its domain is a slab or chimney meeting the sphere in a region: infinite volume, refused so.
TEST(CuspedDomains, InfiniteVolumeIsRefusedWithItsReason) {
  const Mat4 x = moebius_isometry({{1, 1, 0, 1}, false});
  const Mat4 y = moebius_isometry({{1, Complex(0, 1), 0, 1}, false});
  for (const auto& generators : {std::vector<Mat4>{x}, std::vector<Mat4>{x, y}}) {
    try {
      dirichlet_domain(kH3, generators);
      FAIL() << "a parabolic group has infinite covolume";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("has infinite volume"), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find("not discrete"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace geodesic
