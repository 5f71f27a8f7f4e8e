// Scene documents for loader tests: a valid base document, patched per case, and the error
// message a document produces.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene_loader.h"

namespace geodesic {

inline const std::filesystem::path kSceneDocumentDir =
    std::filesystem::path(GEODESIC_SOURCE_DIR) / "scenes";

// A valid document; each test case patches it (RFC 7386 merge patch: null deletes a key).
inline constexpr const char* kBase = R"({
  "geometry": "euclidean",
  "camera": {"position": [0, 0, 5]},
  "materials": {"red": {"diffuse": [0.8, 0.1, 0.1]}},
  "objects": [{"type": "sphere", "material": "red", "center": [0, 0, 0], "radius": 1}]
})";

inline nlohmann::ordered_json patched(const std::string& patch) {
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(kBase);
  doc.merge_patch(nlohmann::ordered_json::parse(patch));
  return doc;
}

inline Scene parse_patched(const std::string& patch) {
  return parse_scene(patched(patch), kSceneDocumentDir);
}

inline std::string error_of_document(const nlohmann::ordered_json& doc,
                                     const DocumentFiles& files = kSceneDocumentDir) {
  try {
    parse_scene(doc, files);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

inline std::string error_of(const std::string& patch) { return error_of_document(patched(patch)); }

// The single object of a document whose objects array is [object].
inline Scene parse_object(const std::string& object) {
  return parse_patched(R"({"objects": [)" + object + "]}");
}

}  // namespace geodesic
