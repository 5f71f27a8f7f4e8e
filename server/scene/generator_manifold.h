// The scene document's generator-based manifolds (docs/scene-format.md, "Generators"):
//   {"type": "generators", "file": "path.gen"}     Curved Spaces or SnapPy text, relative to
//   {"type": "generators", "text": "..."}           the scene file; or the text inline; or
//   {"type": "generators", "matrices": [[4x4]...]}  matrices acting on column vectors
//   {"type": "lens", "p": 7, "q": 2}                L(p, q) by formula (S3)
// each with an optional "base_point" (exponential coordinates) for the Dirichlet domain.
#pragma once

#include <filesystem>
#include <string>

#include "geometry/model.h"
#include "scene/dirichlet_domain.h"
#include "scene/document_files.h"
#include "scene/json_path.h"

namespace geodesic {

// `type` is "generators" or "lens". Throws SceneError naming the field: a missing or
// unreadable file, malformed matrices, generators of another geometry than `kind`, or a group
// whose Dirichlet domain cannot be built (see dirichlet_domain).
DirichletDomain read_generator_manifold(const JsonNode& node, const std::string& type,
                                        GeometryKind kind, const DocumentFiles& files);

}  // namespace geodesic
