// Which scene a request names, in one type for every way in: a bundled scene by name, a scene
// document (inline, or a file on the command line), or generator text (a Curved Spaces .gen
// file or SnapPy pairing matrices: the default scene inside that space). The WebSocket `open`,
// a render job and `geodesic render` each describe their scene as a SceneSource and resolve it
// here, so the same source gives the same scene, and the same errors, wherever it comes from.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/document_files.h"
#include "scene/scene.h"

namespace geodesic {

// The bundled scene a new connection shows before it asks for another.
inline constexpr const char* kDefaultSceneName = "cornell-box";

struct SceneSource {
  enum class Kind { Bundled, Document, Generators };

  static SceneSource bundled(std::string name);
  static SceneSource inline_document(nlohmann::ordered_json document);
  // `label` names the text in errors ("generators: matrix 2 (line 5): ...") and titles its
  // scene when the text has no comment line.
  static SceneSource generator_text(std::string text, std::string label = "generators");
  // Files given on the command line: a scene document, its files beside it unless `files`
  // says otherwise; a generator file, its scene titled by the file's name.
  static SceneSource document_file(std::filesystem::path path, std::optional<DocumentFiles> files = {});
  static SceneSource generator_file(std::filesystem::path path);

  Kind kind = Kind::Bundled;
  std::string name;                  // Bundled: the scene's name; Generators: the text's label
  nlohmann::ordered_json document;   // Document, inline
  std::string text;                  // Generators, inline
  std::filesystem::path file;        // Document or Generators read from this file instead
  // Where a document's mesh and generator file names resolve; unset: inside the resolver's
  // scene directory and only there (documents from clients, docs/protocol.md).
  std::optional<DocumentFiles> files;
};

// A resolved source: the scene and what to call it.
struct ResolvedScene {
  Scene scene;
  SceneSource::Kind kind = SceneSource::Kind::Bundled;
  // The bundled name; otherwise the document's own name, or "document" when it has none.
  std::string name;
  // Generators: the scene document made from the text (a render job stores it); null otherwise.
  nlohmann::ordered_json generated;
};

// Resolves `source`; bundled scenes are <scene_dir>/<name>.json. Throws SceneError
// "<field>: <reason>": "scene: unknown bundled scene ...", a document's JSON path
// ("objects[2].radius: must be > 0", "(root): ..."), "<label>: matrix <i> (line <l>): ...",
// or "<file>: ..." for a file that cannot be read.
ResolvedScene resolve_scene(const SceneSource& source, const std::filesystem::path& scene_dir);

// The names of the bundled scenes in `scene_dir`, sorted.
std::vector<std::string> bundled_scene_names(const std::filesystem::path& scene_dir);

// "bundled", "document" or "generators": how the protocol's `scene` message names a kind.
const char* source_kind_name(SceneSource::Kind kind);

}  // namespace geodesic
