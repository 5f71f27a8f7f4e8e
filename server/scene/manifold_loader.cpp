#include "scene/manifold_loader.h"

#include <string>
#include <vector>

#include "scene/generator_manifold.h"

namespace geodesic {
namespace {

// Matrices typed into a file carry a few decimal digits, not the bundled ones' 1e-9.
constexpr double kFileTolerance = 1e-6;
// Polyhedron construction and validation are cubic to quartic in the face count.
constexpr std::size_t kMaxFaces = 64;

std::vector<DomainFace> read_faces(const JsonNode& node) {
  const std::size_t n = node.expect_array(1, "a non-empty array of faces");
  if (n > kMaxFaces) node.fail("must have at most " + std::to_string(kMaxFaces) + " faces");
  std::vector<DomainFace> faces;
  for (std::size_t i = 0; i < n; ++i) {
    const JsonNode face = node[i];
    face.expect_object({"normal", "distance", "pairing", "partner"});
    faces.push_back({read_vec3(face.at("normal")), read_number(face.at("distance")),
                     read_matrix(face.at("pairing")),
                     read_int(face.at("partner"), 0, static_cast<int>(n) - 1)});
  }
  return faces;
}

// The geometry a bundled type lives in, or fails naming the type.
void require_geometry(const JsonNode& type, const std::string& name, GeometryKind needed,
                      GeometryKind kind) {
  if (kind != needed)
    type.fail("\"" + name + "\" is a " + geometry_name(needed) +
              " manifold, but the scene's geometry is " + geometry_name(kind));
}

}  // namespace

Manifold read_manifold(const JsonNode& node, GeometryKind kind,
                       const DocumentFiles& files) {
  if (node.value().is_null()) return {};
  if (!node.value().is_object()) node.fail("must be null or an object");
  const JsonNode type = node.at("type");
  const std::string name = read_string(type);
  Manifold m;
  if (name == "none") {
    node.expect_object({"type", "max_crossings"});
  } else if (name == "torus") {
    node.expect_object({"type", "size", "max_crossings"});
    require_geometry(type, name, GeometryKind::Euclidean, kind);
    m = make_torus(kind, read_positive(node.at("size")) / 2);
  } else if (name == "mirrored-dodecahedron" || name == "seifert-weber") {
    node.expect_object({"type", "max_crossings"});
    require_geometry(type, name, GeometryKind::Hyperbolic, kind);
    m = name == "seifert-weber" ? make_seifert_weber_space() : make_mirrored_dodecahedron();
  } else if (name == "poincare-dodecahedral") {
    node.expect_object({"type", "max_crossings"});
    require_geometry(type, name, GeometryKind::Spherical, kind);
    m = make_poincare_dodecahedral_space();
  } else if (name == "generic") {
    node.expect_object({"type", "faces", "max_crossings"});
    m = make_generic(kind, read_faces(node.at("faces")), kFileTolerance);
    validate_manifold(kind, m, kFileTolerance);
  } else if (name == "generators" || name == "lens") {
    m = read_generator_manifold(node, name, kind, files).manifold;
  } else {
    type.fail("unknown manifold type \"" + name +
              "\" (expected \"none\", \"torus\", \"mirrored-dodecahedron\", "
              "\"poincare-dodecahedral\", \"seifert-weber\", \"generic\", \"generators\" or "
              "\"lens\")");
  }
  if (const auto n = node.find("max_crossings")) m.max_crossings = read_int(*n, 0, kMaxCrossings);
  return m;
}

}  // namespace geodesic
