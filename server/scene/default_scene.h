// The scene rendered inside a space known only by its generators (`geodesic render
// --generators`, a file dropped on the browser, the catalogue's bundled scenes): the camera at
// the Dirichlet domain's base point, three coloured spheres and a light around it, and the
// domain's edges, all sized by the domain's in-radius so that they fit any space. In S3 the
// camera moves off the base point when the base point's antipode lies on an edge or a sphere,
// and the light's intensity is set by what all its images bring (scene/spherical_view.h).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "scene/dirichlet_domain.h"

namespace geodesic {

// `manifold` is the document's "manifold" value that yields `domain` (its max_crossings is
// filled in when absent).
nlohmann::ordered_json default_scene_document(const std::string& title, GeometryKind kind,
                                              nlohmann::ordered_json manifold,
                                              const DirichletDomain& domain);

// The default scene of generator text (.gen or SnapPy), inline in the document, named by the
// text's first comment line. `source` names the text in errors (SceneError), and the scene when
// the text has no comment.
nlohmann::ordered_json generator_text_scene(const std::string& text, const std::string& source);

// The default scene of a generator file, named by `path` as given (relative names resolve
// against the directory the document is parsed with).
nlohmann::ordered_json generator_file_scene(const std::string& path);

}  // namespace geodesic
