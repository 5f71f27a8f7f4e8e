// Scene documents at the edges: numbers JSON can hold but a scene cannot use, counts no scene
// needs, degenerate geometry and empty scenes. Each is refused naming the field, or loads into
// something the renderer can take.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include <stdlib.h>

#include "render/prepare/emitters.h"
#include "scene_document.h"

namespace geodesic {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

TEST(SceneLimits, HugeNumbersAreRefusedNamingTheField) {
  const std::pair<std::string, std::string> cases[] = {
      {R"({"camera": {"position": [1e308, 0, 5]}})",
       "camera.position[0]: must have magnitude <= 1e6"},
      {R"({"camera": {"position": [0, -1e308, 5]}})",
       "camera.position[1]: must have magnitude <= 1e6"},
      {R"({"camera": {"fov_y": 1e308}})", "camera.fov_y: must be in (0, 180)"},
      {R"({"objects": [{"type": "sphere", "material": "red", "center": [0, 0, 0],
           "radius": 1e308}]})", "objects[0].radius: must be <= 1e6"},
      {R"({"objects": [{"type": "sphere", "material": "red", "center": [0, 0, 0],
           "radius": -1e308}]})", "objects[0].radius: must be > 0"},
      // Integers beyond int64 and uint64 (the latter parses as a double).
      {R"({"render": {"width": 9223372036854775808}})",
       "render.width: must be an integer in [1, 8192]"},
      {R"({"render": {"width": 100000000000000000000000}})",
       "render.width: must be an integer in [1, 8192]"},
      {R"({"render": {"spp": 4294967297}})", "render.spp: must be an integer in [1, 1000000]"},
      {R"({"render": {"spp": -9223372036854775808}})",
       "render.spp: must be an integer in [1, 1000000]"},
      {R"({"render": {"seed": 1e300}})", "render.seed: must be an unsigned integer"},
  };
  for (const auto& [patch, message] : cases) EXPECT_EQ(error_of(patch), message) << patch;
  // The largest seed is a seed.
  EXPECT_EQ(parse_patched(R"({"render": {"seed": 18446744073709551615}})").render.seed,
            18446744073709551615u);
}

// JSON has no NaN or infinity; 1e400 overflows double, and the file loader names the number.
TEST(SceneLimits, NumberOverflowInAFileIsInvalidJson) {
  std::string dir = (fs::temp_directory_path() / "geodesic-overflow-XXXXXX").string();
  ASSERT_TRUE(mkdtemp(dir.data()));
  const fs::path file = fs::path(dir) / "overflow.json";
  std::ofstream(file) << R"({"geometry": "euclidean", "camera": {"position": [0, 0, 1e400]}})";
  try {
    load_scene_file(file);
    ADD_FAILURE() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              file.string() + ": invalid JSON: number overflow parsing '1e400'");
  }
  fs::remove_all(dir);
}

// A million objects is refused from the array's size, before any element is read (the array
// of nulls here is 16 MB; a million spheres would be hundreds).
TEST(SceneLimits, CountsBeyondAnySceneAreRefused) {
  Json doc = patched("{}");
  doc["objects"] = Json::array();
  doc["objects"].get_ref<Json::array_t&>().resize(1000000);
  EXPECT_EQ(error_of_document(doc),
            "objects: has 1000000 elements; at most 10000 are allowed");

  doc = patched("{}");
  doc["lights"] = Json::array();
  doc["lights"].get_ref<Json::array_t&>().resize(1001);
  EXPECT_EQ(error_of_document(doc), "lights: has 1001 elements; at most 1000 are allowed");

  // A polygon's convexity check is quadratic in its vertices.
  Json vertices = Json::array();
  for (int i = 0; i < 1001; ++i) {
    const double angle = 2 * std::numbers::pi * i / 1001;
    vertices.push_back({std::cos(angle), std::sin(angle), 0});
  }
  doc = patched("{}");
  doc["objects"] = {{{"type", "polygon"}, {"material", "red"}, {"vertices", vertices}}};
  EXPECT_EQ(error_of_document(doc),
            "objects[0].vertices: has 1001 elements; at most 1000 are allowed");
  // 1000 pass the count and reach the convexity check (so close to a circle, neighbours count
  // as collinear).
  vertices.erase(vertices.end() - 1);
  doc["objects"][0]["vertices"] = vertices;
  EXPECT_EQ(error_of_document(doc),
            "objects[0].vertices: polygon must be strictly convex (no reflex, repeated or "
            "collinear vertices)");
}

// No objects and no lights is a valid (black) scene: nothing to build, nothing to sample.
TEST(SceneLimits, EmptySceneLoads) {
  const Scene scene = parse_patched(R"({"objects": [], "lights": []})");
  EXPECT_TRUE(scene.spheres.empty());
  EXPECT_TRUE(scene.meshes.empty());
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_TRUE(build_emitters(scene).emitters.empty());
  const Scene bare = parse_patched(R"({"materials": null, "objects": null})");
  EXPECT_TRUE(bare.materials.empty());
  EXPECT_TRUE(bare.spheres.empty());
}

// A mesh file with a zero-area triangle and one with a repeated vertex loads (ray tracing never
// hits them); as an emitter, only the real triangle is sampled.
TEST(SceneLimits, DegenerateMeshTrianglesAreNeverSampled) {
  std::string dir = (fs::temp_directory_path() / "geodesic-degenerate-XXXXXX").string();
  ASSERT_TRUE(mkdtemp(dir.data()));
  std::ofstream(fs::path(dir) / "degenerate.obj") << "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\n"
                                                     "f 1 2 3\nf 1 2 2\nf 1 2 4\n";
  Json doc = patched(R"({"materials": {"lamp": {"emission": 1}}})");
  doc["objects"] = {{{"type", "mesh"}, {"material", "lamp"}, {"file", "degenerate.obj"}}};
  const Scene scene = parse_scene(doc, fs::path(dir));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].indices.size(), 9u);
  const EmitterTable table = build_emitters(scene);
  ASSERT_EQ(table.emitters.size(), 1u);
  EXPECT_EQ(table.triangle_emitter.at(0).at(0), EmitterTable::kNone);
  EXPECT_EQ(table.triangle_emitter.at(0).at(1), EmitterTable::kNone);
  EXPECT_NE(table.triangle_emitter.at(0).at(2), EmitterTable::kNone);
  EXPECT_FLOAT_EQ(table.emitters[0].cdf, 1.0f);
  fs::remove_all(dir);
}

// A document from a client (confined to the scene directory) cannot make the server read its
// other files: a generator file's first token would come back in the error message.
TEST(SceneLimits, ClientDocumentsNameOnlyFilesInTheSceneDirectory) {
  const DocumentFiles confined(kSceneDocumentDir, /*confined=*/true);
  const std::string outside = "must name a file inside the scene directory";
  for (const char* name : {"/etc/passwd", "../CMakeLists.txt", "meshes/../../README.md",
                           "/nonexistent/file.obj"}) {
    Json doc = patched("{}");
    doc["objects"] = {{{"type", "mesh"}, {"material", "red"}, {"file", name}}};
    EXPECT_EQ(error_of_document(doc, confined), "objects[0].file: " + outside) << name;
    doc = patched(R"({"objects": null})");
    doc["manifold"] = {{"type", "generators"}, {"file", name}};
    EXPECT_EQ(error_of_document(doc, confined), "manifold.file: " + outside) << name;
  }
  Json doc = patched("{}");
  doc["objects"] = {{{"type", "mesh"}, {"material", "red"}, {"file", "meshes/octahedron.obj"}}};
  EXPECT_EQ(parse_scene(doc, confined).meshes.size(), 1u);
  // Trusted documents (files on disk) may still reach out, as the catalogue's scenes do.
  doc["objects"][0]["file"] = "../scenes/meshes/octahedron.obj";
  EXPECT_EQ(parse_scene(doc, kSceneDocumentDir).meshes.size(), 1u);
}

}  // namespace
}  // namespace geodesic
