// Scene documents naming their space by generators: a .gen file relative to the scene, inline
// text or matrices, lens spaces by formula, the default scene, and errors naming the field.
#include "scene/generator_manifold.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/catalogue.h"
#include "scene/default_scene.h"
#include "scene/generator_file.h"
#include "scene/scene_loader.h"
#include "test_constants.h"

namespace geodesic {
namespace {

using test::kSource;

Scene parse(const std::string& geometry, const std::string& manifold) {
  const auto doc = nlohmann::ordered_json::parse(
      R"({"geometry": ")" + geometry + R"(", "manifold": )" + manifold +
      R"(, "camera": {"position": [0, 0, 0], "look_at": [0, 0, -0.1]}})");
  return parse_scene(doc, kSource / "scenes" / "catalogue");
}

std::string manifold_error_of(const std::string& geometry, const std::string& manifold) {
  try {
    parse(geometry, manifold);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(GeneratorManifold, FileRelativeToTheScene) {
  const Scene s = parse("spherical", R"({"type": "generators", "file": "../../catalogue/binary-octahedral.gen"})");
  EXPECT_EQ(s.manifold.faces.size(), 14u);
  EXPECT_EQ(s.manifold.name, "generators");
}

TEST(GeneratorManifold, InlineTextAndMatrices) {
  const std::string text = catalogue_gen_text(*find_catalogue_entry("hantzsche-wendt"));
  const Scene a = parse("euclidean", R"({"type": "generators", "text": )" +
                                         nlohmann::json(text).dump() + "}");
  EXPECT_EQ(a.manifold.faces.size(), 12u);
  // Column-vector matrices: the 3-torus of side 2.
  const Scene b = parse("euclidean", R"({"type": "generators", "matrices": [
      [[1,0,0,2],[0,1,0,0],[0,0,1,0],[0,0,0,1]],
      [[1,0,0,0],[0,1,0,2],[0,0,1,0],[0,0,0,1]],
      [[1,0,0,0],[0,1,0,0],[0,0,1,2],[0,0,0,1]]], "max_crossings": 9})");
  EXPECT_EQ(b.manifold.faces.size(), 6u);
  EXPECT_EQ(b.manifold.max_crossings, 9);
  EXPECT_NEAR(b.manifold.faces[0].delta, 1.0, 1e-12);
}

TEST(GeneratorManifold, LensSpaceByFormula) {
  const Scene s = parse("spherical", R"({"type": "lens", "p": 7, "q": 2})");
  EXPECT_EQ(s.manifold.faces.size(), 6u);
  EXPECT_NE(manifold_error_of("spherical", R"({"type": "lens", "p": 6, "q": 4})")
                .find("manifold.q: lens space L(6, 4): p and q must be coprime"),
            std::string::npos);
  // L(p, 1) preserves a great circle: its domain is charted in pieces, one cell each.
  EXPECT_GT(parse("spherical", R"({"type": "lens", "p": 9, "q": 1})").manifold.pieces.size(), 8u);
  EXPECT_NE(manifold_error_of("euclidean", R"({"type": "lens", "p": 5, "q": 2})")
                .find("manifold.type: the generators are isometries of spherical space, but the "
                      "scene's geometry is euclidean"),
            std::string::npos);
}

TEST(GeneratorManifold, ErrorsNameTheField) {
  EXPECT_NE(manifold_error_of("euclidean", R"({"type": "generators", "file": "missing.gen"})")
                .find("manifold.file: "),
            std::string::npos);
  EXPECT_NE(manifold_error_of("euclidean", R"({"type": "generators"})")
                .find("manifold: needs exactly one of \"file\", \"text\" or \"matrices\""),
            std::string::npos);
  EXPECT_NE(manifold_error_of("euclidean", R"({"type": "generators", "text": "1 0 0 0\n0 1 0 0\n0 0 1\n0 0 0 1\n"})")
                .find("manifold.text: matrix 1 (line 3): row 3 has 3 entries, not 4"),
            std::string::npos);
  EXPECT_NE(manifold_error_of("euclidean", R"({"type": "generators", "matrices": [[[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]]})")
                .find("manifold.matrices: matrix 1: not an isometry"),
            std::string::npos);
}

// Seifert-Weber's generators with one entry off by 1e-7: still isometries within the parser's
// tolerance (files carry 6 to 20 digits), but no longer the group meant. The error says what
// the enumeration found and that the matrices are inexact, not only "not compact".
TEST(GeneratorManifold, ANearIsometryThatBreaksTheGroupIsNamedAsTheLikelyCause) {
  const std::vector<Mat4> exact = find_catalogue_entry("seifert-weber")->generators;
  const std::string fine = nlohmann::json(format_gen(exact, "#\tSeifert-Weber")).dump();
  EXPECT_EQ(manifold_error_of("hyperbolic", R"({"type": "generators", "text": )" + fine + "}"), "(no error)");
  std::vector<Mat4> sheared = exact;
  sheared[0].m[0][1] += 1e-7;
  const std::string text = nlohmann::json(format_gen(sheared, "#\tSheared")).dump();
  const std::string error = manifold_error_of("hyperbolic", R"({"type": "generators", "text": )" + text + "}");
  EXPECT_TRUE(error.starts_with("manifold: generators: ")) << error;
  EXPECT_NE(error.find("note: the matrices are isometries only to "), std::string::npos) << error;
  EXPECT_NE(error.find("can generate another group than the one meant: give them to more digits"),
            std::string::npos)
      << error;
}

// The default scene: the camera at the base point, three spheres, a light and the domain's
// edges, all inside the domain (the loader checks), for a space of each geometry.
TEST(DefaultScene, FitsTheDomainOfEachGeometry) {
  for (const char* name : {"sixth-turn", "lens-11-3", "seifert-weber"}) {
    const CatalogueEntry& e = *find_catalogue_entry(name);
    const Scene s = parse_scene(generator_text_scene(catalogue_gen_text(e), name), {});
    EXPECT_EQ(s.geometry, e.kind) << name;
    EXPECT_EQ(s.name, e.title) << "named by the text's first comment line";
    EXPECT_EQ(s.spheres.size(), 3u) << name;
    EXPECT_EQ(s.lights.size(), 1u) << name;
    EXPECT_FALSE(s.manifold.faces.empty()) << name;
    const DirichletDomain d = dirichlet_domain(e.kind, e.generators);
    for (const Sphere& sphere : s.spheres)
      EXPECT_LT(length(sphere.center) + sphere.radius, d.inradius) << name;
  }
}

TEST(DefaultScene, NamedByTheFirstCommentOrTheSource) {
  const std::string matrix =  // the cubic 3-torus, rows acting on row vectors
      "1 0 0 0\n0 1 0 0\n0 0 1 0\n2 0 0 1\n\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 2 0 1\n\n"
      "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 2 1\n";
  auto name = [&](const std::string& text) { return generator_text_scene(text, "dropped")["name"]; };
  EXPECT_EQ(name("\xEF\xBB\xBF#\tMirrored Lens with dihedral angle 2\xCF\x80/6\r\n#\n\n" + matrix),
            "Mirrored Lens with dihedral angle 2\xCF\x80/6");
  EXPECT_EQ(name("\n  #   \n# Slab  \n" + matrix), "Slab");
  EXPECT_EQ(name(matrix + "# trailing\n"), "dropped");
  EXPECT_EQ(name(matrix), "dropped");
}

// The schema declares the new manifold types with every field the catalogue's scenes use.
TEST(GeneratorManifold, SchemaDeclaresTheCatalogueScenesFields) {
  std::ifstream in(kSource / "proto" / "scene.schema.json");
  const auto schema = nlohmann::json::parse(in);
  nlohmann::json generators, lens;
  for (const auto& option : schema.at("properties").at("manifold").at("oneOf"))
    if (option.contains("properties")) {
      const auto type = option.at("properties").at("type").value("const", "");
      if (type == "generators") generators = option;
      if (type == "lens") lens = option;
    }
  ASSERT_TRUE(generators.is_object() && lens.is_object());
  for (const char* field : {"p", "q", "base_point", "max_crossings"})
    EXPECT_TRUE(lens.at("properties").contains(field)) << field;
  for (const CatalogueEntry& e : catalogue()) {
    std::ifstream scene_in(kSource / "scenes" / "catalogue" / (e.name + ".json"));
    const auto scene = nlohmann::json::parse(scene_in);
    for (const auto& item : scene.items())
      EXPECT_TRUE(schema.at("properties").contains(item.key())) << e.name << "." << item.key();
    for (const auto& item : scene.at("manifold").items())
      EXPECT_TRUE(generators.at("properties").contains(item.key()))
          << e.name << ".manifold." << item.key();
  }
}

}  // namespace
}  // namespace geodesic
