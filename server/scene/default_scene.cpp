#include "scene/default_scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "scene/cusp_neighbourhoods.h"
#include "scene/generator_file.h"
#include "scene/manifold.h"

namespace geodesic {
namespace {

using Json = nlohmann::ordered_json;

Json vec(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

// Diffuse plus specular stays below 1 (energy conservation).
Json material(const Vec3& colour) {
  return {{"ambient", vec(colour)}, {"diffuse", vec(colour)}, {"specular", 0.3}, {"shininess", 30}};
}

// Enough face crossings to see a few copies of the domain: in S3 a ray returns after 2 pi,
// about pi / inradius domains. In a closed E3 or H3 space every geodesic meets something in
// the end, so one cut off at the cap is black where the scene is not (docs/numerics.md): the
// largest cap, as the bundled quotients have. At 24 the catalogue's tori came out 12 % too
// dark, its amphicosms 22-26 % and its Coxeter orthoschemes 27-32 %. A cusped space's rays end
// on its horospheres, some only after many thin copies: the largest cap too.
int crossings_for(GeometryKind kind, double inradius) {
  if (kind != GeometryKind::Spherical) return kMaxCrossings;
  return std::clamp(static_cast<int>(std::ceil(std::numbers::pi / inradius)) + 8, 16,
                    kMaxCrossings);
}

}  // namespace

Json default_scene_document(const std::string& title, GeometryKind kind, Json manifold,
                            const DirichletDomain& domain) {
  const double r = domain.inradius;
  // A domain cut into pieces (chart_atlas.h) has no edges in one chart to draw; the walls
  // between its pieces do not count as crossings.
  const bool pieces = !domain.manifold.pieces.empty();
  if (!manifold.contains("max_crossings"))
    manifold["max_crossings"] = crossings_for(kind, r);
  // Sphere centres at 0.55 r and radii 0.18 r keep every sphere inside the in-ball; the light's
  // intensity goes with r^2, as its distance to the spheres does (small domains are nearly flat).
  const Vec3 red = normalize(Vec3{0.5, 0.1, -0.85}) * (0.55 * r);
  const Vec3 green = normalize(Vec3{-0.6, 0.35, -0.7}) * (0.55 * r);
  const Vec3 blue = normalize(Vec3{0.1, -0.65, 0.75}) * (0.55 * r);
  Json objects = Json::array();
  for (const auto& [name, centre] : {std::pair{"red", red}, {"green", green}, {"blue", blue}})
    objects.push_back({{"type", "sphere"}, {"material", name}, {"center", vec(centre)},
                       {"radius", 0.18 * r}});
  // A cusped domain's edges run out to the sphere at infinity, where no tube fits the chart;
  // its cusps are cut off by horospheres of a faintly glowing sky instead.
  const std::vector<CuspHorosphere> cusps =
      domain.cusps > 0 ? cusp_horospheres(domain.manifold) : std::vector<CuspHorosphere>{};
  for (const CuspHorosphere& c : cusps)
    objects.push_back({{"type", "horosphere"}, {"material", "cusp" + std::to_string(c.cusp)},
                       {"direction", vec(c.direction)}, {"distance", c.distance}});
  if (!pieces && cusps.empty())
    objects.push_back({{"type", "domain_edges"}, {"material", "edge"}, {"radius", 0.02 * r}});
  Json materials = {{"edge", {{"ambient", vec({0.85, 0.7, 0.35})}, {"diffuse", vec({0.85, 0.7, 0.35})}}},
                    {"red", material({0.68, 0.13, 0.08})},
                    {"green", material({0.13, 0.6, 0.17})},
                    {"blue", material({0.13, 0.26, 0.68})}};
  const Vec3 skies[] = {{0.55, 0.7, 0.95}, {0.95, 0.65, 0.45}, {0.6, 0.9, 0.6}};
  for (int k = 0; k < domain.cusps; ++k) {
    const Vec3 sky = skies[k % 3];
    materials["cusp" + std::to_string(k)] = {
        {"ambient", vec(sky)}, {"diffuse", vec(sky * 0.5)}, {"emission", vec(sky * 0.3)}};
  }
  return {
      {"name", title},
      {"geometry", geometry_name(kind)},
      {"manifold", manifold},
      {"camera", {{"position", vec({0, 0, 0})}, {"look_at", vec({0, 0, -0.5 * r})}, {"fov_y", 80}}},
      {"materials", materials},
      {"objects", objects},
      {"lights", Json::array({{{"type", "point"},
                               {"position", vec(Vec3{0.1, 0.6, 0.2} * r)},
                               {"intensity", std::min(1.0, 2 * r * r)}}})},
      {"render",
       {{"width", 512}, {"height", 512}, {"max_depth", 1}, {"spp", 16}, {"seed", 1u},
        {"ambient", 0.25}}}};
}

Json generator_text_scene(const std::string& text, const std::string& source) {
  const GeneratorSet set = parse_generators(text, source);
  const DirichletDomain domain = dirichlet_domain(set.kind, set.generators);
  return default_scene_document(set.title.empty() ? source : set.title, set.kind,
                                {{"type", "generators"}, {"text", text}}, domain);
}

Json generator_file_scene(const std::string& path) {
  const GeneratorSet set = load_generator_file(path);
  const DirichletDomain domain = dirichlet_domain(set.kind, set.generators);
  return default_scene_document(std::filesystem::path(path).stem().string(), set.kind,
                                {{"type", "generators"}, {"file", path}}, domain);
}

}  // namespace geodesic
