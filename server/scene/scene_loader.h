// Reads a scene document (JSON, see proto/scene.schema.json) into a Scene.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "scene/document_files.h"
#include "scene/scene.h"

namespace geodesic {

// `files` resolves mesh and generator file names (a directory, or one confined to it for
// documents from clients). Throws SceneError naming the field and reason.
// Takes ordered_json because material indices follow document order; a plain
// nlohmann::json converts implicitly but has already sorted its keys.
Scene parse_scene(const nlohmann::ordered_json& doc, const DocumentFiles& files);
// Also throws SceneError for an unreadable file or invalid JSON (with the parse position).
// The document's files (meshes, generator files) resolve beside it, or within `files`.
Scene load_scene_file(const std::filesystem::path& path);
Scene load_scene_file(const std::filesystem::path& path, const DocumentFiles& files);

}  // namespace geodesic
