// Generator text: Curved Spaces .gen files (row vectors, transposed on reading) and SnapPy's
// O(3,1) pairing matrices (time first), the geometry they imply, and errors that name the
// matrix, the line and the reason.
#include "scene/generator_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "scene/catalogue.h"
#include "scene/dirichlet_domain.h"
#include "scene/scene.h"

namespace geodesic {
namespace {

std::string generator_error_of(const std::string& text) {
  try {
    parse_generators(text, "test.gen");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

const char* kHalfTurn =
    "\xEF\xBB\xBF# Half turn space\n"
    "#   comment lines, then blank-separated 4x4 blocks\n\n"
    " 1 0 0 0\n 0 1 0 0\n 0 0 1 0\n 1 0 0 1\n\n"
    " 1 0 0 0\n 0 1 0 0\n 0 0 1 0\n 0 1 0 1   # trailing comment\n\n"
    "-1 0 0 0\n 0 -1 0 0\n 0 0 1 0\n 0 0 1 1\n";

TEST(GeneratorFile, ReadsCurvedSpacesTextTransposed) {
  const GeneratorSet set = parse_generators(kHalfTurn, "half-turn.gen");
  EXPECT_EQ(set.kind, GeometryKind::Euclidean);
  ASSERT_EQ(set.generators.size(), 3u);
  // Row-vector translation in the bottom row becomes our last column.
  EXPECT_EQ(set.generators[0].m[0][3], 1.0);
  EXPECT_EQ(set.generators[0].m[3][0], 0.0);
  EXPECT_EQ(set.generators[2].m[2][3], 1.0);
  EXPECT_EQ(set.generators[2].m[0][0], -1.0);
  const DirichletDomain d = dirichlet_domain(set.kind, set.generators);
  EXPECT_NEAR(d.volume, 1.0, 1e-12);  // 1 x 1 x 2 lattice, holonomy 2
}

TEST(GeneratorFile, DetectsEachGeometry) {
  for (const char* name : {"half-turn", "binary-octahedral", "seifert-weber"}) {
    const CatalogueEntry& e = *find_catalogue_entry(name);
    EXPECT_EQ(parse_generators(catalogue_gen_text(e), name).kind, e.kind) << name;
  }
}

TEST(GeneratorFile, ErrorsNameMatrixLineAndReason) {
  EXPECT_EQ(generator_error_of("1 0 0 0\n0 1 0 0\n0 0 1\n0 0 0 1\n"),
            "test.gen: matrix 1 (line 3): row 3 has 3 entries, not 4");
  EXPECT_EQ(generator_error_of("1 0 0 0\n0 1 0 0\n0 0 1 0\n"),
            "test.gen: matrix 1 (line 1): has 3 rows, not 4 (matrices are 4x4)");
  EXPECT_EQ(generator_error_of("1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n\n1 0 0 0\n0 1 x 0\n0 0 1 0\n2 0 0 1\n"),
            "test.gen: matrix 2 (line 7): \"x\" is not a number");
  EXPECT_EQ(generator_error_of("1 0 0 0\n0 1 0 0\n0 0 nan 0\n2 0 0 1\n"),
            "test.gen: matrix 1 (line 3): entry \"nan\" is not finite");
  EXPECT_NE(generator_error_of("2 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n")
                .find("matrix 1 (line 1): not an isometry of euclidean, hyperbolic or spherical"),
            std::string::npos);
  // A translation (E3 only) then a turn in the zw plane (S3 only).
  EXPECT_NE(generator_error_of("1 0 0 0\n0 1 0 0\n0 0 1 0\n1 0 0 1\n\n"
                     "1 0 0 0\n0 1 0 0\n0 0 0 1\n0 0 -1 0\n")
                .find("matrix 2 (line 6): is an isometry of spherical space only, but the "
                      "matrices before it are not (euclidean)"),
            std::string::npos);
  EXPECT_NE(generator_error_of("# nothing\n").find("no matrices"), std::string::npos);
  EXPECT_NE(generator_error_of("0 -1 0 0\n1 0 0 0\n0 0 1 0\n0 0 0 1\n").find("ambiguous"),
            std::string::npos);
}

// SnapPy prints O(3,1) matrices with the time coordinate first; the Seifert-Weber pairings
// written that way come back as our matrices and give the same domain.
TEST(GeneratorFile, ReadsSnapPyPairingMatrices) {
  const CatalogueEntry& sw = *find_catalogue_entry("seifert-weber");
  const int from_ours[4] = {3, 0, 1, 2};  // SnapPy index i holds our coordinate from_ours[i]
  std::string text = "[";
  for (std::size_t k = 0; k < sw.generators.size(); ++k) {
    text += k ? ",\n Matrix([" : "Matrix([";
    for (int r = 0; r < 4; ++r) {
      text += r ? ", [" : "[";
      for (int c = 0; c < 4; ++c) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%s%.17g", c ? ", " : "",
                      sw.generators[k].m[from_ours[r]][from_ours[c]]);
        text += buf;
      }
      text += "]";
    }
    text += "])";
  }
  text += "]";
  const GeneratorSet set = parse_generators(text, "snappy.txt");
  EXPECT_EQ(set.kind, GeometryKind::Hyperbolic);
  ASSERT_EQ(set.generators.size(), sw.generators.size());
  for (std::size_t k = 0; k < set.generators.size(); ++k)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(set.generators[k].m[r][c], sw.generators[k].m[r][c], 1e-15);
  EXPECT_NEAR(dirichlet_domain(set.kind, set.generators).volume, sw.volume, 1e-8);
  EXPECT_EQ(generator_error_of("[[1, 0, 0, 0], [0, 1, 0]]"),
            "test.gen: matrix 1 (line 1): row 2, [0, 1, 0], has 3 entries, not 4");
  EXPECT_EQ(generator_error_of("[[1, 0, 0, 0], [0, 1, 0, 0],\n [0, 0, 1, 0], [0, 0, 0, 1]],\n[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0, 0]]"),
            "test.gen: matrix 2 (line 3): row 3, [0, 0, 1, 0, 0], has 5 entries, not 4");
}

// Junk inside a row (a request's bytes pasted into an entry, a word, a stray character) is
// refused by name while reading, in either bracket format; words between rows are not rows.
TEST(GeneratorFile, RefusesJunkInsideARowByName) {
  EXPECT_EQ(generator_error_of("[[1, 1], [0, 1]]\n[[5 - 0.866OST /api/j{aobs 025403784scene*I  1], [0, 1]]"),
            "test.gen: matrix 2 (line 2): \"OST\" inside [5 - 0.866OST /api/j{aobs "
            "025403784scene*I  1] is not part of a number");
  EXPECT_NE(generator_error_of("[[1, 1], [0, 1]]\n[[1, 0], [0.5 / 2, 1]]").find("matrix 2 (line 2): \"/\""),
            std::string::npos);
  EXPECT_NE(generator_error_of("[[1, nan], [0, 1]]").find("\"nan\" inside [1, nan]"), std::string::npos);
  EXPECT_NE(generator_error_of("[[1, 0, 0, 0], [0, 1, 0, 0],\n [0, 0, 1, 0], [0, 0, 0, 1]],\n"
                     "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0],\n [0, x1, 0, 1]]")
                .find("matrix 2 (line 4): \"x1\" inside [0, x1, 0, 1]"),
            std::string::npos);
  // An imaginary unit is no part of an O(3,1) entry.
  EXPECT_NE(generator_error_of("[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 2*I, 1]]").find("\"I\""),
            std::string::npos);
  // Entry characters out of place: what a fuzzer once got past the reader as two Moebius
  // matrices, whose domain search then ran for seconds before refusing them.
  EXPECT_EQ(generator_error_of("# m004%2e%2e\n[.  1+0j), 2j], [-1j, (1-2j  1+0j), 2j], [-1j, (1-)]]"),
            "test.gen: matrix 1 (line 2): a \".\" has no digit beside it inside [.  1+0j), 2j]");
  EXPECT_NE(generator_error_of("[[1, 1], [0, 1+0j)]]").find("matrix 1 (line 1): a \")\" closes no \"(\" "
                                                  "inside [0, 1+0j)]"),
            std::string::npos);
  EXPECT_NE(generator_error_of("[[1, 1], [0, (1-)]]").find("a \"-\" has no number after it inside [0, (1-)]"),
            std::string::npos);
  EXPECT_NE(generator_error_of("[[1, 1], [0, (1+2j]]").find("a \"(\" is not closed inside [0, (1+2j]"),
            std::string::npos);
  EXPECT_NE(generator_error_of("[[1, 1], [0, *I]]").find("a \"*\" follows no number"), std::string::npos);
  EXPECT_NE(generator_error_of("[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 2*, 1]]")
                .find("matrix 1 (line 1): a \"*\" is not followed by an imaginary unit"),
            std::string::npos);
  // Entries outside every row would be read into a matrix: refused by name. A fuzzer's
  // unclosed row read "1 186602540378" into a Moebius matrix moving the origin by 26.
  EXPECT_EQ(generator_error_of("# m004\n[1 ?186602540378n\n[1 (1-2j)]]"),
            "test.gen: matrix 1 (line 2): \"1\" lies outside every row [...]: entries belong "
            "inside rows");
  EXPECT_EQ(generator_error_of("[[1, 1], [0, 1]] 2\n[[1, 0], [0, 1]]"),
            "test.gen: matrix 2 (line 1): \"2\" lies outside every row [...]: entries belong "
            "inside rows");
  EXPECT_NE(generator_error_of("[[1, 1], j [0, 1]]").find("\"j\" lies outside every row"),
            std::string::npos);
  // A Moebius entry is named whole, as its reader would take it, on its own line.
  EXPECT_NE(generator_error_of("[[1, 1],\n\n 0.5 - 2*I [0, 1]]")
                .find("matrix 1 (line 3): \"0.5 - 2*I\" lies outside every row"),
            std::string::npos);
  EXPECT_NE(generator_error_of("[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], [0.5").find(
                "matrix 2 (line 1): \"0.5\" lies outside every row"),
            std::string::npos);
  // Exponents, units, Python's complex literals and words outside rows still read.
  const GeneratorSet set = parse_generators(
      "G = [Matrix([[1, 1.5e-1j], [0, 1]]), conj Matrix([[(1+0j), 0], [0, 1E+0]])]", "m.txt");
  EXPECT_EQ(set.generators.size(), 2u);
  EXPECT_EQ(parse_generators("[[1., -.5*I], [0, 1]]\n[[1, 2.5E-1 - 1*i], [0, 1]]", "s.txt")
                .generators.size(),
            2u);
}

TEST(GeneratorFile, FormatRoundTrips) {
  const CatalogueEntry& e = *find_catalogue_entry("binary-icosahedral");
  const GeneratorSet set = parse_generators(format_gen(e.generators, "header\n\nmore"), "x");
  ASSERT_EQ(set.generators.size(), e.generators.size());
  for (std::size_t k = 0; k < set.generators.size(); ++k)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) EXPECT_EQ(set.generators[k].m[r][c], e.generators[k].m[r][c]);
}

}  // namespace
}  // namespace geodesic
