#include "scene/generator_manifold.h"

#include <algorithm>
#include <cstdio>

#include "scene/catalogue.h"
#include "scene/generator_file.h"

namespace geodesic {
namespace {

// The generators and the field to blame for them.
GeneratorSet read_set(const JsonNode& node, const DocumentFiles& files) {
  const auto file = node.find("file"), text = node.find("text"), matrices = node.find("matrices");
  if (int(bool(file)) + int(bool(text)) + int(bool(matrices)) != 1)
    node.fail("needs exactly one of \"file\", \"text\" or \"matrices\"");
  if (file) {
    const std::filesystem::path path = files.resolve(*file);
    try {
      return load_generator_file(path);
    } catch (const SceneError& e) {
      file->fail(e.what());  // "<path>: matrix <i> (line <l>): reason"
    }
  }
  if (text) return parse_generators(read_string(*text), text->path());
  const std::size_t n = matrices->expect_array(1, "a non-empty array of 4x4 matrices");
  std::vector<Mat4> generators;
  for (std::size_t i = 0; i < n; ++i) generators.push_back(read_matrix((*matrices)[i]));
  return generator_set(generators, matrices->path());  // its errors name the field
}

// Below this relative isometry error, matrices are exact to double round-off.
constexpr double kExactIsometry = 1e-12;

// The largest isometry error of the matrices, relative to their size as the parser bounds it.
double inexactness(GeometryKind kind, const std::vector<Mat4>& generators) {
  double worst = 0;
  for (const Mat4& g : generators) {
    const double size = std::max(1.0, g.max_abs());
    worst = std::max(worst, model::isometry_error(kind, g) /
                                (kind == GeometryKind::Euclidean ? 1 : size * size));
  }
  return worst;
}

}  // namespace

DirichletDomain read_generator_manifold(const JsonNode& node, const std::string& type,
                                        GeometryKind kind, const DocumentFiles& files) {
  GeneratorSet set;
  if (type == "lens") {
    node.expect_object({"type", "p", "q", "base_point", "max_crossings"});
    const JsonNode p = node.at("p"), q = node.at("q");
    set.kind = GeometryKind::Spherical;
    try {
      set.generators = lens_space_generators(read_int(p, 2, 1000), read_int(q, -1000, 1000));
    } catch (const SceneError& e) {
      q.fail(e.what());
    }
  } else {
    node.expect_object({"type", "file", "text", "matrices", "base_point", "max_crossings"});
    set = read_set(node, files);
  }
  if (set.kind != kind)
    node.at("type").fail("the generators are isometries of " + std::string(geometry_name(set.kind)) +
                         " space, but the scene's geometry is " + geometry_name(kind));
  DirichletOptions options;
  if (const auto b = node.find("base_point")) options.base_point = read_vec3(*b);
  try {
    return dirichlet_domain(kind, set.generators, options);
  } catch (const SceneError& e) {
    // Matrices accepted as isometries within the parser's tolerance are snapped to exact
    // ones, but the group they generate may no longer be the one meant (a 1e-7 shear of
    // Seifert-Weber's generators breaks its relations): say so when that may be the cause.
    std::string message = e.what();
    if (const double off = inexactness(kind, set.generators); off > kExactIsometry) {
      char figure[32];
      std::snprintf(figure, sizeof figure, "%.1e", off);
      message += "; note: the matrices are isometries only to " + std::string(figure) +
                 " (relative), and entries rounded or perturbed that much can generate another "
                 "group than the one meant: give them to more digits";
    }
    node.fail(message);
  }
}

}  // namespace geodesic
