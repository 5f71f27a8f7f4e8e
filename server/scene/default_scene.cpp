#include "scene/default_scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "scene/cusp_neighbourhoods.h"
#include "scene/generator_file.h"
#include "scene/manifold.h"
#include "scene/spherical_view.h"

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

// S3: the light's intensity makes the irradiance that all its images bring to the centre of
// the sphere they light most this much. Every image shines on every point there, so the rule
// for a lone light (intensity going with the in-radius squared) left the scenes of large
// groups washed out and of small ones dark: at 11-13 (the prism spaces) renders came out at
// 78-93 of 255 in mean sRGB code, at 23-43 (the binary tetrahedral, octahedral and
// icosahedral groups) at 122-174 with desaturated spheres, at 2.3 (projective space) at 32.
constexpr double kSphereIrradiance = 13;

// S3: the camera moves off the domain's centre when the centre's antipode comes closer than
// this (times the in-radius) to an edge's tube or a sphere: every geodesic from the camera passes
// through its antipode, so what lies there fills the whole background (an edge of L(5,2) does).
constexpr double kAntipodeClearance = 0.1;

// Where to put the camera, and how bright to make the light, in a spherical space (see above).
struct SphericalView {
  Vec3 eye;
  double intensity = 1;  // the light's
};

SphericalView spherical_view(const DirichletDomain& domain, const std::vector<Vec3>& spheres,
                             double sphere_radius, double edge_radius, const Vec3& light) {
  constexpr GeometryKind k = GeometryKind::Spherical;
  const std::vector<Mat4> group = spherical_group(domain.manifold);
  SphericalView view;
  double irradiance = 0;
  std::vector<BallObstacle> balls;
  for (const Vec3& c : spheres) {
    const Vec4 centre = model::exp_origin(k, c);
    irradiance = std::max(irradiance, orbit_irradiance(group, model::exp_origin(k, light), centre));
    balls.push_back({centre, sphere_radius});
  }
  view.intensity = kSphereIrradiance / irradiance;
  // The centre, else the clearest of points a quarter in-radius from it.
  const double r = domain.inradius;
  auto clearance = [&](const Vec3& eye) {
    return antipode_clearance(group, domain.manifold.domain, edge_radius, balls,
                              model::exp_origin(k, eye));
  };
  double best = clearance(view.eye);
  if (best >= kAntipodeClearance * r) return view;
  for (const Vec3& d : {Vec3{0, 0, -1}, Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0},
                        Vec3{0, -1, 0}, Vec3{0, 0, 1}, normalize(Vec3{1, 1, -1}),
                        normalize(Vec3{-1, 1, -1}), normalize(Vec3{1, -1, -1}),
                        normalize(Vec3{-1, -1, -1})})
    if (const double c = clearance(d * (0.25 * r)); c > best) best = c, view.eye = d * (0.25 * r);
  return view;
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
  // In S3 the light's intensity is set by all its images, and the camera may move off the base
  // point (spherical_view).
  const Vec3 red = normalize(Vec3{0.5, 0.1, -0.85}) * (0.55 * r);
  const Vec3 green = normalize(Vec3{-0.6, 0.35, -0.7}) * (0.55 * r);
  const Vec3 blue = normalize(Vec3{0.1, -0.65, 0.75}) * (0.55 * r);
  const Vec3 light = Vec3{0.1, 0.6, 0.2} * r;
  double intensity = std::min(1.0, 2 * r * r);
  Vec3 eye{0, 0, 0};
  if (kind == GeometryKind::Spherical) {
    const SphericalView view =
        spherical_view(domain, {red, green, blue}, 0.18 * r, pieces ? 0 : 0.02 * r, light);
    eye = view.eye;
    intensity = view.intensity;
  }
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
      {"camera", {{"position", vec(eye)}, {"look_at", vec(eye + Vec3{0, 0, -0.5 * r})}, {"fov_y", 80}}},
      {"materials", materials},
      {"objects", objects},
      {"lights", Json::array({{{"type", "point"},
                               {"position", vec(light)},
                               {"intensity", intensity}}})},
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
