// Reads the scene document's "manifold" field (see docs/scene-format.md, "Manifolds").
#pragma once

#include <filesystem>

#include "geometry/model.h"
#include "scene/document_files.h"
#include "scene/json_path.h"
#include "scene/manifold.h"

namespace geodesic {

// `node` is the "manifold" value (null means no quotient; an absent field is the caller's
// default-constructed Manifold). Throws SceneError naming the field: an unknown type, a type
// for another geometry, malformed fields, or a generic domain that fails validate_manifold.
// `files` resolves a generator file's name.
Manifold read_manifold(const JsonNode& node, GeometryKind kind,
                       const DocumentFiles& files = {});

}  // namespace geodesic
