// Dirichlet domains from generators: the catalogue's closed forms against their known orders
// and volumes, Jeff Weeks' Curved Spaces generator files (test data outside the project), lens
// spaces by formula, base points and the precision reached.
#include "scene/dirichlet_domain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include "scene/catalogue.h"
#include "scene/generator_file.h"
#include "scene/scene.h"
#include "test_constants.h"

namespace geodesic {
namespace {

namespace fs = std::filesystem;
using test::kPi;
using test::kSource;
const fs::path kCurvedSpaces = kSource / ".." / "shared" / "data" / "curved-spaces-gen";

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every edge cycle closes with order 1: the group acts freely (a manifold, not an orbifold).
bool acts_freely(GeometryKind kind, const Manifold& m) {
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    if (m.faces[f].partner == static_cast<int>(f)) return false;
  for (const EdgeCycle& c : edge_cycles(kind, m))
    if (c.order != 1) return false;
  return true;
}

TEST(Catalogue, EveryEntryHasItsOrderVolumeAndExactPairings) {
  ASSERT_GE(catalogue().size(), 25u);
  std::map<GeometryKind, int> per_geometry;
  for (const CatalogueEntry& e : catalogue()) {
    SCOPED_TRACE(e.name);
    ++per_geometry[e.kind];
    const DirichletDomain d = dirichlet_domain(e.kind, e.generators);
    EXPECT_NEAR(d.volume, e.volume, 1e-9 * e.volume);
    EXPECT_EQ(d.finite, e.group_order.has_value());
    if (e.group_order) EXPECT_EQ(d.elements, static_cast<std::size_t>(*e.group_order));
    EXPECT_LT(d.isometry_error, 1e-14);
    EXPECT_LT(d.product_drift, 1e-12);
    EXPECT_EQ(acts_freely(e.kind, d.manifold), !e.orbifold);
    EXPECT_GT(d.inradius, 0);
    EXPECT_LE(d.inradius, d.circumradius);
  }
  EXPECT_GE(per_geometry[GeometryKind::Euclidean], 8);
  EXPECT_GE(per_geometry[GeometryKind::Spherical], 12);
  EXPECT_GE(per_geometry[GeometryKind::Hyperbolic], 5);
}

TEST(Catalogue, KnownDomainShapes) {
  auto faces = [](const std::string& name) {
    const CatalogueEntry& e = *find_catalogue_entry(name);
    return dirichlet_domain(e.kind, e.generators).manifold.faces.size();
  };
  EXPECT_EQ(faces("3-torus"), 6u);            // cube
  EXPECT_EQ(faces("hexagonal-torus"), 8u);    // hexagonal prism
  EXPECT_EQ(faces("hantzsche-wendt"), 12u);   // rhombic dodecahedron
  EXPECT_EQ(faces("binary-dihedral-2"), 6u);  // the quaternionic cube
  EXPECT_EQ(faces("binary-tetrahedral"), 8u);  // octahedron
  EXPECT_EQ(faces("binary-octahedral"), 14u);  // truncated cube
  EXPECT_EQ(faces("binary-icosahedral"), 12u);  // Poincare's dodecahedron
  EXPECT_EQ(faces("lens-5-2"), 4u);  // the tetrahedral space L(5, 2)
  EXPECT_EQ(faces("seifert-weber"), 12u);
  EXPECT_EQ(faces("mirrored-dodecahedron"), 12u);
  for (const char* tetrahedron : {"coxeter-3-5-3", "coxeter-5-3-4", "coxeter-5-3-5"})
    EXPECT_EQ(faces(tetrahedron), 4u) << tetrahedron;  // the kaleidoscope is its own domain
}

TEST(Catalogue, CommittedFilesAreTheGeneratorsOutput) {
  for (const CatalogueEntry& e : catalogue()) {
    SCOPED_TRACE(e.name);
    const fs::path gen = kSource / "catalogue" / (e.name + ".gen");
    ASSERT_TRUE(fs::exists(gen)) << "run `geodesic catalogue` in the source root";
    EXPECT_EQ(read_text(gen), catalogue_gen_text(e));
    EXPECT_TRUE(fs::exists(kSource / "scenes" / "catalogue" / (e.name + ".json")));
    // The file's 20 decimals give back the closed form.
    const GeneratorSet set = load_generator_file(gen);
    EXPECT_EQ(set.kind, e.kind);
    ASSERT_EQ(set.generators.size(), e.generators.size());
    for (std::size_t i = 0; i < set.generators.size(); ++i)
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
          EXPECT_NEAR(set.generators[i].m[r][c], e.generators[i].m[r][c], 1e-15);
  }
  EXPECT_EQ(read_text(kSource / "catalogue" / "README.md"), catalogue_readme());
}

TEST(LensSpaces, AnyCoprimePairByFormula) {
  for (const auto& [p, q] : {std::pair{5, 3}, {8, 5}, {13, 5}, {17, 4}, {24, 7}, {40, 9}}) {
    SCOPED_TRACE("L(" + std::to_string(p) + "," + std::to_string(q) + ")");
    const DirichletDomain d = dirichlet_domain(GeometryKind::Spherical, lens_space_generators(p, q));
    EXPECT_EQ(d.elements, static_cast<std::size_t>(p));
    EXPECT_NEAR(d.volume, 2 * kPi * kPi / p, 1e-9);
    EXPECT_TRUE(acts_freely(GeometryKind::Spherical, d.manifold));
  }
}

TEST(LensSpaces, ClearErrors) {
  EXPECT_THROW(
      {
        try {
          lens_space_generators(6, 4);
        } catch (const SceneError& e) {
          EXPECT_NE(std::string(e.what()).find("coprime (gcd 2)"), std::string::npos) << e.what();
          throw;
        }
      },
      SceneError);
  EXPECT_THROW(lens_space_generators(1, 0), SceneError);
}

// The pieces of a domain charted apart lie within pi / 3 of their centres, and their gluings
// are mutual: the partner's partner is the face, the pairings inverse.
void expect_atlas_glued(const DirichletDomain& d) {
  ASSERT_GE(d.manifold.pieces.size(), 2u);
  EXPECT_TRUE(d.manifold.domain.vertices.empty());
  std::vector<const PieceFace*> all;
  for (const DomainPiece& piece : d.manifold.pieces) {
    for (const Vec3& v : piece.polyhedron.vertices) EXPECT_LE(length(v), std::sqrt(3.0) + 1e-9);
    for (const PieceFace& f : piece.faces) all.push_back(&f);
  }
  for (std::size_t f = 0; f < all.size(); ++f) {
    const PieceFace& back = *all[all[f]->partner];
    EXPECT_EQ(back.partner, static_cast<int>(f));
    const Mat4 loop = back.pairing * all[f]->pairing;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(loop.m[r][c], r == c ? 1 : 0, 1e-12);
  }
}

// Projective space, L(p, 1) and L(p, p - 1) preserve a great circle: no domain fits one
// gnomonic chart, so the Dirichlet domain is cut into pieces charted apart (chart_atlas.h),
// more than eight past RP3 (the renderer's cells then share ray-mask bits).
TEST(LensSpaces, GreatCircleGroupsAreChartedInPieces) {
  constexpr auto kS3 = GeometryKind::Spherical;
  for (const auto& [p, q] : {std::pair{2, 1}, {3, 1}, {7, 1}, {6, 5}, {40, 1}, {1000, 1}, {999, 998}}) {
    SCOPED_TRACE("L(" + std::to_string(p) + "," + std::to_string(q) + ")");
    const DirichletDomain d = dirichlet_domain(kS3, lens_space_generators(p, q));
    EXPECT_EQ(d.elements, static_cast<std::size_t>(p));
    EXPECT_NEAR(d.volume, 2 * kPi * kPi / p, 1e-9);
    EXPECT_NEAR(d.inradius, kPi / p, 1e-12);  // the orbit of the origin is a great circle
    EXPECT_LT(d.isometry_error, 1e-14);
    expect_atlas_glued(d);
    // A lune cut like an orange through its arc, at the p angles its twist turns into each
    // other; projective space (the antipodal map) is cut by Voronoi cells.
    if (p >= 4) EXPECT_EQ(d.manifold.pieces.size(), static_cast<std::size_t>(p));
  }
  // Past the renderer's cells: refused at once, with the count.
  try {
    dirichlet_domain(kS3, lens_space_generators(1100, 1));
    ADD_FAILURE() << "L(1100, 1) needs 1100 pieces";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("more than 1024 chart pieces"), std::string::npos) << e.what();
  }
}

// The mirrored lenses fix a great circle pointwise: their lune is charted in pieces too, and
// the pieces of its two mirror faces are glued to themselves by the reflections.
TEST(LensSpaces, MirroredLensesGlueMirrorPiecesToThemselves) {
  for (int n : {4, 6, 8, 24}) {
    SCOPED_TRACE("mirrored lens " + std::to_string(n));
    const DirichletDomain d = dirichlet_domain(GeometryKind::Spherical, mirrored_lens_generators(n));
    EXPECT_EQ(d.elements, static_cast<std::size_t>(n));
    EXPECT_NEAR(d.volume, 2 * kPi * kPi / n, 1e-9);
    EXPECT_NEAR(d.inradius, kPi / n, 1e-12);  // half the lune's angle 2 pi / n
    expect_atlas_glued(d);
    EXPECT_EQ(d.manifold.pieces.size(), 4u);  // the lune cut at four angles about its edge
    int self_glued = 0, faces = 0;
    for (const DomainPiece& piece : d.manifold.pieces)
      for (const PieceFace& f : piece.faces) self_glued += f.partner == faces++;
    EXPECT_GE(self_glued, 2) << "each mirror holds at least one piece's face";
  }
  EXPECT_THROW(mirrored_lens_generators(5), SceneError);
  EXPECT_THROW(mirrored_lens_generators(2), SceneError);
}

TEST(DirichletDomain, BasePointMovesTheDomainNotTheSpace) {
  const CatalogueEntry& sw = *find_catalogue_entry("seifert-weber");
  DirichletOptions options;
  options.base_point = Vec3{0.2, -0.1, 0.3};
  const DirichletDomain d = dirichlet_domain(sw.kind, sw.generators, options);
  EXPECT_NEAR(d.volume, sw.volume, 1e-8);
  EXPECT_NEAR(d.base_point.x, 0.2, 1e-15);
  EXPECT_GT(d.manifold.faces.size(), 12u);  // a generic point: no longer the dodecahedron
}

TEST(DirichletDomain, FixedBasePointIsMovedOff) {
  // The mirrored dodecahedron's reflections fix points on its faces; a base point on a mirror
  // is nudged off it.
  const CatalogueEntry& m = *find_catalogue_entry("mirrored-dodecahedron");
  DirichletOptions options;
  const Vec3 n = dodecahedron_normals()[0];
  options.base_point = n * std::atanh(std::pow(5.0, -0.25));  // on face 0's plane
  const DirichletDomain d = dirichlet_domain(m.kind, m.generators, options);
  EXPECT_GT(length(d.base_point - *options.base_point), 1e-3);
  EXPECT_NEAR(d.volume, m.volume, 1e-8);
}

TEST(DirichletDomain, NonCompactAndEmptyInputs) {
  EXPECT_THROW(dirichlet_domain(GeometryKind::Euclidean, {}), SceneError);
  const Mat4 shift = model::translation(GeometryKind::Euclidean, {1, 0, 0});
  try {
    dirichlet_domain(GeometryKind::Euclidean, {shift});
    FAIL() << "one translation leaves the domain unbounded";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("unbounded"), std::string::npos) << e.what();
  }
  // Two translations: a discrete group whose slab of a domain is unbounded; not "not
  // discrete", as it used to say when the enumeration reached its cap.
  const Mat4 other = model::translation(GeometryKind::Euclidean, {0, 2, 0});
  try {
    dirichlet_domain(GeometryKind::Euclidean, {shift, other});
    FAIL() << "two translations leave the domain unbounded";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("unbounded"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("spanning only a plane"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("not discrete"), std::string::npos) << e.what();
  }
  // One hyperbolic translation, and two along one axis: discrete, not cocompact (the cell is a
  // slab); they used to say "fixed by a group element: not discrete", once products far out
  // lost precision and two words for one power stopped agreeing.
  const Mat4 boost = model::translation(GeometryKind::Hyperbolic, {1, 0, 0});
  const Mat4 longer = model::translation(GeometryKind::Hyperbolic, {2.5, 0, 0});
  for (const auto& generators : {std::vector<Mat4>{boost}, std::vector<Mat4>{boost, longer}}) {
    try {
      dirichlet_domain(GeometryKind::Hyperbolic, generators);
      FAIL() << "hyperbolic translations along one axis leave the domain unbounded";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("hyperbolic space by these generators has infinite volume"),
                std::string::npos)
          << e.what();
      EXPECT_EQ(std::string(e.what()).find("not discrete"), std::string::npos) << e.what();
    }
  }
  // Generators moving the origin beyond double precision's reach in H3 (the fuzzer's Moebius
  // matrix with an entry 1.9e11 moved it by 26): said so at once, with the distance, instead
  // of enumerating products whose images overflowed the orbit's hash grid.
  const Mat4 far = model::translation(GeometryKind::Hyperbolic, {0, 26, 0});
  const Mat4 farther = model::translation(GeometryKind::Hyperbolic, {27, 0, 0});
  try {
    dirichlet_domain(GeometryKind::Hyperbolic, {farther, far});
    FAIL() << "generators moving the origin by 26";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "generators: the shortest generator (after shortening the set) moves the base "
              "point by 26, beyond distance 10, within which double precision tells the "
              "elements of an H3 group apart");
  }
}

// Curved Spaces' files: every one parses and gives a valid domain whose volume matches the
// group order (S3) or the known volume (H3); the lenses that preserve a great circle too, in
// chart pieces, and the mirrored lenses (mirrors through one great circle), whose pieces on a
// mirror are glued to themselves.
TEST(CurvedSpacesFiles, AllParseAndBuildDomains) {
  if (!fs::exists(kCurvedSpaces)) GTEST_SKIP() << "test data not found at " << kCurvedSpaces;
  // Group orders (the catalogue's binary dihedral D*n has order 4n) and volumes: the Weeks
  // manifold 0.9427073628 and Thurston's 0.9813688289 (SnapPea census), Seifert-Weber and the
  // right-angled dodecahedron as in the catalogue.
  const std::map<std::string, std::size_t> kOrders = {
      {"Spherical Cube", 8},         {"Binary Dihedral 2 L", 8},   {"Binary Dihedral 3 L", 12},
      {"Binary Dihedral 4 L", 16},   {"Binary Dihedral 6 L", 24},  {"Binary Dihedral 8 L", 32},
      {"Binary Dihedral 12 L", 48},  {"Binary Tetrahedral L", 24}, {"Binary Icosahedral L", 120},
      {"Tetrahedral Space = L(5,2)", 5}, {"Mirrored Tetrahedron", 16}, {"Projective 3-Space", 2},
      {"Lens(24,1) L", 24},          {"Mirrored Lens 4", 4},       {"Mirrored Lens 6", 6},
      {"Mirrored Lens 8", 8},        {"Mirrored Lens 12", 12},     {"Mirrored Lens 24", 24}};
  const std::map<std::string, double> kVolumes = {
      {"Hyperbolic First", 0.9427073628},
      {"Hyperbolic Second", 0.9813688289},
      {"Seifert Weber R", find_catalogue_entry("seifert-weber")->volume},
      {"Mirrored Dodecahedron", find_catalogue_entry("mirrored-dodecahedron")->volume},
      {"Hantzsche Wendt", 2.0}};
  std::size_t checked = 0;
  int files = 0, built = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kCurvedSpaces)) {
    if (entry.path().extension() != ".gen") continue;
    ++files;
    const std::string name = entry.path().stem().string();
    SCOPED_TRACE(entry.path().string());
    if (name == "3-Sphere") {  // no generators at all
      EXPECT_THROW(load_generator_file(entry.path()), SceneError);
      continue;
    }
    const GeneratorSet set = load_generator_file(entry.path());
    const DirichletDomain d = dirichlet_domain(set.kind, set.generators);
    ++built;
    EXPECT_LT(d.isometry_error, 1e-14);
    EXPECT_LT(d.product_drift, 1e-12);
    if (set.kind == GeometryKind::Spherical) {
      EXPECT_TRUE(d.finite);
      EXPECT_NEAR(d.volume * d.elements, 2 * kPi * kPi, 1e-8);
    }
    if (const auto it = kOrders.find(name); it != kOrders.end()) {
      EXPECT_EQ(d.elements, it->second);
      ++checked;
    }
    if (const auto it = kVolumes.find(name); it != kVolumes.end()) {
      EXPECT_NEAR(d.volume, it->second, 1e-9);
      ++checked;
    }
  }
  EXPECT_EQ(checked, kOrders.size() + kVolumes.size() + 1);  // the mirrored dodecahedron twice
  EXPECT_EQ(files, 46);
  EXPECT_EQ(built, 45);  // all but the 3-sphere, which has no generators
}

}  // namespace
}  // namespace geodesic
