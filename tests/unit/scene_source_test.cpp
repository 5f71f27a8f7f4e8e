// SceneSource (scene/scene_source.h), the one resolution the WebSocket, jobs and the command
// line share: each kind of source gives the scene it names, and a bad source an error naming
// the field and the reason.
#include "scene/scene_source.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "scene_document.h"

namespace geodesic {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

const fs::path kCatalogue = fs::path(GEODESIC_SOURCE_DIR) / "catalogue";

std::string text_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string source_error_of(const SceneSource& source) {
  try {
    resolve_scene(source, kSceneDocumentDir);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SceneSource, TheDefaultSceneIsBundled) {
  const auto names = bundled_scene_names(kSceneDocumentDir);
  EXPECT_NE(std::find(names.begin(), names.end(), kDefaultSceneName), names.end());
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
}

TEST(SceneSource, ABundledNameResolvesToItsFile) {
  const ResolvedScene resolved = resolve_scene(SceneSource::bundled("cornell-box"), kSceneDocumentDir);
  EXPECT_EQ(resolved.kind, SceneSource::Kind::Bundled);
  EXPECT_EQ(resolved.name, "cornell-box");
  EXPECT_TRUE(resolved.generated.is_null());
  // cornell-box.json: eight quads (two triangles each, in meshes), three spheres, one light.
  const Scene& scene = resolved.scene;
  EXPECT_EQ(scene.geometry, GeometryKind::Euclidean);
  EXPECT_EQ(scene.spheres.size(), 3u);
  EXPECT_EQ(scene.lights.size(), 1u);
  EXPECT_TRUE(scene.name.starts_with("Cornell box"));
  EXPECT_EQ(scene.render.max_depth, 5);
  // The same scene the file gives when loaded directly.
  const Scene direct = load_scene_file(kSceneDocumentDir / "cornell-box.json");
  EXPECT_EQ(scene.meshes.size(), direct.meshes.size());
  EXPECT_EQ(scene.materials.size(), direct.materials.size());
}

TEST(SceneSource, AnInlineDocumentIsParsedWithItsFilesInTheSceneDirectory) {
  Json doc = patched(R"({"name": "two spheres", "objects": [
      {"type": "sphere", "material": "red", "center": [0, 0, 0], "radius": 1},
      {"type": "sphere", "material": "red", "center": [3, 0, 0], "radius": 0.5},
      {"type": "mesh", "material": "red", "file": "meshes/octahedron.obj"}]})");
  const ResolvedScene resolved = resolve_scene(SceneSource::inline_document(doc), kSceneDocumentDir);
  EXPECT_EQ(resolved.kind, SceneSource::Kind::Document);
  EXPECT_EQ(resolved.name, "two spheres");
  ASSERT_EQ(resolved.scene.spheres.size(), 2u);
  EXPECT_DOUBLE_EQ(resolved.scene.spheres[1].radius, 0.5);
  ASSERT_EQ(resolved.scene.meshes.size(), 1u);
  EXPECT_EQ(resolved.scene.meshes[0].indices.size(), 8u * 3u);  // an octahedron's faces

  doc.erase("name");
  EXPECT_EQ(resolve_scene(SceneSource::inline_document(doc), kSceneDocumentDir).name, "document");
}

TEST(SceneSource, GeneratorTextBecomesTheDefaultSceneOfItsSpace) {
  const std::string text = text_of(kCatalogue / "3-torus.gen");
  const ResolvedScene resolved = resolve_scene(SceneSource::generator_text(text), kSceneDocumentDir);
  EXPECT_EQ(resolved.kind, SceneSource::Kind::Generators);
  EXPECT_EQ(resolved.name, "Cubic 3-torus");  // the text's first comment line
  EXPECT_EQ(resolved.scene.geometry, GeometryKind::Euclidean);
  EXPECT_EQ(resolved.scene.manifold.faces.size(), 6u);  // the cube's faces, paired
  EXPECT_EQ(resolved.scene.spheres.size(), 3u);         // red, green, blue
  EXPECT_EQ(resolved.scene.lights.size(), 1u);
  // The generated document is what a job stores: it holds the text, and parses to the same.
  EXPECT_EQ(resolved.generated["manifold"]["text"], text);
  EXPECT_EQ(parse_scene(resolved.generated, {}).manifold.faces.size(), 6u);

  // Without a comment line, the label names it.
  const std::string bare = text.substr(text.find("\n\n") + 2);
  EXPECT_EQ(resolve_scene(SceneSource::generator_text(bare, "dropped"), kSceneDocumentDir).name,
            "dropped");
}

TEST(SceneSource, FilesOnTheCommandLineResolve) {
  const ResolvedScene scene =
      resolve_scene(SceneSource::document_file(kSceneDocumentDir / "mesh-demo.json"), {});
  EXPECT_EQ(scene.kind, SceneSource::Kind::Document);
  EXPECT_FALSE(scene.scene.meshes.empty());  // its mesh file, found beside it

  const ResolvedScene space =
      resolve_scene(SceneSource::generator_file(kCatalogue / "binary-icosahedral.gen"), {});
  EXPECT_EQ(space.kind, SceneSource::Kind::Generators);
  EXPECT_EQ(space.name, "binary-icosahedral");  // a file's scene is titled by the file's name
  EXPECT_EQ(space.scene.geometry, GeometryKind::Spherical);
  EXPECT_EQ(space.scene.manifold.faces.size(), 12u);  // the dodecahedron
}

TEST(SceneSource, BadSourcesNameTheFieldAndTheReason) {
  EXPECT_EQ(source_error_of(SceneSource::bundled("no-such-scene")),
            "scene: unknown bundled scene \"no-such-scene\"");
  // A name is a listed scene, never a path.
  EXPECT_EQ(source_error_of(SceneSource::bundled("../scenes/cornell-box")),
            "scene: unknown bundled scene \"../scenes/cornell-box\"");
  EXPECT_EQ(source_error_of(SceneSource::inline_document(patched(
                R"({"objects": [{"type": "sphere", "material": "red", "center": [0, 0, 0], "radius": -1}]})"))),
            "objects[0].radius: must be > 0");
  // A client's document may name files inside the scene directory only.
  EXPECT_EQ(source_error_of(SceneSource::inline_document(patched(
                R"({"objects": [{"type": "mesh", "material": "red", "file": "../CMakeLists.txt"}]})"))),
            "objects[0].file: must name a file inside the scene directory");
  const std::string generators = source_error_of(SceneSource::generator_text("1 0 0\n0 1 0\n"));
  EXPECT_TRUE(generators.starts_with("generators: matrix 1")) << generators;
  const std::string missing = source_error_of(SceneSource::document_file("no/such/scene.json"));
  EXPECT_EQ(missing, "no/such/scene.json: cannot open file (missing or not a regular file)");
}

}  // namespace
}  // namespace geodesic
