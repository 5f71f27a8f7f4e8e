// The one place a scene source becomes a Scene (scene_source.h): bundled names are checked
// against the scene directory's listing before any file is read, documents from clients
// resolve their files inside that directory only, and generator text becomes the default scene
// of its space (default_scene.h).
#include "scene/scene_source.h"

#include <algorithm>
#include <utility>

#include "scene/default_scene.h"
#include "scene/scene_loader.h"

namespace geodesic {

SceneSource SceneSource::bundled(std::string name) {
  SceneSource source;
  source.kind = Kind::Bundled;
  source.name = std::move(name);
  return source;
}

SceneSource SceneSource::inline_document(nlohmann::ordered_json document) {
  SceneSource source;
  source.kind = Kind::Document;
  source.document = std::move(document);
  return source;
}

SceneSource SceneSource::generator_text(std::string text, std::string label) {
  SceneSource source;
  source.kind = Kind::Generators;
  source.text = std::move(text);
  source.name = std::move(label);
  return source;
}

SceneSource SceneSource::document_file(std::filesystem::path path,
                                       std::optional<DocumentFiles> files) {
  SceneSource source;
  source.kind = Kind::Document;
  source.files = files ? std::move(files) : DocumentFiles(path.parent_path());
  source.file = std::move(path);
  return source;
}

SceneSource SceneSource::generator_file(std::filesystem::path path) {
  SceneSource source;
  source.kind = Kind::Generators;
  source.name = path.string();
  source.files = DocumentFiles();  // the generated document names the file as given
  source.file = std::move(path);
  return source;
}

ResolvedScene resolve_scene(const SceneSource& source, const std::filesystem::path& scene_dir) {
  using Kind = SceneSource::Kind;
  ResolvedScene resolved;
  resolved.kind = source.kind;
  const DocumentFiles files = source.files.value_or(DocumentFiles(scene_dir, /*confined=*/true));
  switch (source.kind) {
    case Kind::Bundled: {
      const auto names = bundled_scene_names(scene_dir);
      if (std::find(names.begin(), names.end(), source.name) == names.end())
        throw SceneError("scene: unknown bundled scene \"" + source.name + "\"");
      resolved.scene = load_scene_file(scene_dir / (source.name + ".json"));
      resolved.name = source.name;
      return resolved;
    }
    case Kind::Document:
      resolved.scene = source.file.empty() ? parse_scene(source.document, files)
                                           : load_scene_file(source.file, files);
      break;
    case Kind::Generators:
      // The generated document holds its text inline, or names the file as given.
      resolved.generated = source.file.empty() ? generator_text_scene(source.text, source.name)
                                               : generator_file_scene(source.file.string());
      resolved.scene = parse_scene(resolved.generated, files);
      break;
  }
  resolved.name = resolved.scene.name.empty() ? "document" : resolved.scene.name;
  return resolved;
}

std::vector<std::string> bundled_scene_names(const std::filesystem::path& scene_dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(scene_dir))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

const char* source_kind_name(SceneSource::Kind kind) {
  switch (kind) {
    case SceneSource::Kind::Bundled: return "bundled";
    case SceneSource::Kind::Document: return "document";
    case SceneSource::Kind::Generators: return "generators";
  }
  return "document";
}

}  // namespace geodesic
