// The physical model against closed forms: white furnaces in E3, H3 and S3 (radiance
// L_e / (1 - albedo)), a point light's irradiance I cos / A(d) on a small patch in each
// geometry, and light sampling (NEE + MIS) agreeing with BSDF sampling alone.
#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/model.h"
#include "render/prepare/emitters.h"
#include "render_fixture.h"

namespace geodesic::test {
namespace {

// A closed grey sphere around the camera, albedo 0.5 and emission 1: every pixel converges to
// 1 / (1 - 0.5) = 2.
std::string sphere_furnace(const char* geometry, double radius) {
  return std::string(R"({"geometry": ")") + geometry + R"(",
    "camera": {"position": [0.1, -0.2, 0.15], "rotation": {"yaw": 30, "pitch": 10}, "fov_y": 90},
    "materials": {"grey": {"diffuse": 0.5, "emission": 1}},
    "objects": [{"type": "sphere", "material": "grey", "center": [0, 0, 0], "radius": )" +
         std::to_string(radius) + R"(}],
    "render": {"width": 24, "height": 24, "max_depth": 40, "lighting": "physical"}})";
}

void expect_furnace(const Scene& scene, uint32_t spp) {
  Renderer renderer(device(), scene);
  renderer.add_samples(spp);
  const Rgb m = mean(renderer.image());
  EXPECT_NEAR(m.r, 2.0, 0.02) << scene.name;
  EXPECT_NEAR(m.g, 2.0, 0.02);
  EXPECT_NEAR(m.b, 2.0, 0.02);
  EXPECT_EQ(renderer.non_finite_samples(), 0u);
}

TEST(WhiteFurnace, EuclideanBoxOfEmittingTriangles) {
  Scene scene = load_scene_file(source_path("scenes/furnace.json"));
  scene.render.lighting = LightingModel::Physical;
  scene.render.width = scene.render.height = 24;
  expect_furnace(scene, 256);
}

TEST(WhiteFurnace, HyperbolicSphere) { expect_furnace(scene_from_json(sphere_furnace("hyperbolic", 1.5)), 256); }

TEST(WhiteFurnace, SphericalSphere) { expect_furnace(scene_from_json(sphere_furnace("spherical", 1.2)), 256); }

// Enclosures from small to large under the default model (MIS): inside a large sphere light
// sampling sees it in every direction (in S3 past r = pi/2 the sphere also holds the
// camera's antipode, and geodesics longer than pi reach its wall); within 1 %. (In H3 from
// r = 4 the tracer itself loses paths, with BSDF sampling alone too: docs/numerics.md.)
TEST(WhiteFurnace, EnclosuresOfSeveralSizes) {
  for (double r : {0.3, 1.0, 3.0}) expect_furnace(scene_from_json(sphere_furnace("hyperbolic", r)), 256);
  for (double r : {0.5, 2.0, 2.8}) expect_furnace(scene_from_json(sphere_furnace("spherical", r)), 256);
}

// Without next-event estimation the furnace converges to the same value: emission found by
// BSDF sampling alone.
TEST(WhiteFurnace, BsdfSamplingAloneAgrees) {
  Scene scene = scene_from_json(sphere_furnace("hyperbolic", 1.5));
  scene.render.light_sampling = LightSampling::Bsdf;
  expect_furnace(scene, 256);
}

// A white Lambertian patch (albedo 0.5) facing a point light of intensity 3 at the camera:
// radiance 0.5 / pi * 3 / A(d) with A(d) = d^2, sinh^2 d or sin^2 d.
void expect_point_light_falloff(GeometryKind kind, double d) {
  const double half = 0.02;
  const std::string doc = std::string(R"({"geometry": ")") + geometry_name(kind) + R"(",
    "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov_y": 0.5},
    "materials": {"white": {"diffuse": 0.5}},
    "objects": [{"type": "quad", "material": "white", "corner": [)" + std::to_string(-half) +
    ", " + std::to_string(-half) + ", " + std::to_string(-d) + R"(],
      "edge_u": [)" + std::to_string(2 * half) + R"(, 0, 0], "edge_v": [0, )" +
    std::to_string(2 * half) + R"(, 0]}],
    "lights": [{"type": "point", "position": [0, 0, 0], "intensity": 3}],
    "render": {"width": 8, "height": 8, "max_depth": 0, "lighting": "physical"}})";
  const Scene scene = scene_from_json(doc);
  // The quad's corners lie at distance d along their own directions; its centre, where the
  // axis meets the chart plane through them, is a little nearer in H3 and S3.
  const Vec4 corner = model::exp_origin(kind, {half, half, -d});
  const Vec4 centre = model::lift(kind, {0, 0, corner.z / corner.w});
  const double distance = model::geodesic_distance(kind, model::origin(), centre);
  const double expected = 0.5 / M_PI * 3 / model::sphere_area_factor(kind, distance);
  const Rgb m = mean(render(scene, 16));
  EXPECT_NEAR(luminance_of(m), expected, 0.02 * expected)
      << geometry_name(kind) << " at distance " << distance;
}

TEST(PointLight, IrradianceFallsOffAsOneOverAreaFactor) {
  for (GeometryKind kind : {GeometryKind::Euclidean, GeometryKind::Hyperbolic, GeometryKind::Spherical})
    expect_point_light_falloff(kind, 1.2);
  expect_point_light_falloff(GeometryKind::Hyperbolic, 2.5);  // sinh^2 d, not d^2: 6x apart
  expect_point_light_falloff(GeometryKind::Spherical, 2.4);   // past pi/2: sin^2 d grows again
}

// A point light in a quotient reaches a point along one geodesic per image (and in S3 also
// the long way round): next-event estimation picks one of them in proportion to I cos / A(d)
// (shaders/lights/emitters.glsl, by inverting the running sum at a Sobol dimension), so the
// mean over samples must be the whole sum. A small white patch (albedo 0.5) at the cell's
// centre, nothing else in the space, so no image is hidden: the radiance is
// 0.5 / pi * I * sum over the kept images and branches of max(0, cos) / A(d).
void expect_point_light_images_sum(const std::string& geometry, const std::string& manifold,
                                   const Vec3& light, double cutoff, int light_samples = 1) {
  const double half = 0.004;
  const Scene scene = scene_from_json(R"({"geometry": ")" + geometry + R"(", "manifold": )" +
    manifold + R"(, "camera": {"position": [0, 0, 0.05], "look_at": [0, 0, 0], "fov_y": 4},
    "materials": {"white": {"diffuse": 0.5}},
    "objects": [{"type": "quad", "material": "white", "corner": [)" + std::to_string(-half) +
    ", " + std::to_string(-half) + R"(, 0], "edge_u": [)" + std::to_string(2 * half) +
    R"(, 0, 0], "edge_v": [0, )" + std::to_string(2 * half) + R"(, 0]}],
    "lights": [{"type": "point", "position": [)" + std::to_string(light.x) + ", " +
    std::to_string(light.y) + ", " + std::to_string(light.z) + R"(], "intensity": 1}],
    "render": {"width": 8, "height": 8, "max_depth": 0, "lighting": "physical",
               "light_cutoff": )" + std::to_string(cutoff) + R"(, "light_samples": )" +
    std::to_string(light_samples) + "}}");
  const GeometryKind kind = scene.geometry;
  const EmitterTable table = build_emitters(scene);
  ASSERT_EQ(table.emitters.size(), 1u);
  const GpuEmitter& e = table.emitters[0];
  ASSERT_GT(e.image_count, 8u) << "a test of the choice among images needs many";
  const bool antipodal = manifold.find("poincare") != std::string::npos;
  if (kind == GeometryKind::Spherical) EXPECT_NEAR(table.cutoff, antipodal ? M_PI : 2 * M_PI, 1e-5);
  const Vec4 x = model::origin(), normal{0, 0, 1, 0};
  // Where the group holds -1 an image stands for itself and its antipode, and then the
  // images cover the whole group, the binary icosahedral group's 120 elements: every copy of
  // the light lies within the cutoff of pi.
  EXPECT_EQ(e.antipodal_pairs != 0, antipodal);
  if (antipodal) EXPECT_EQ(2 * e.image_count, 120u);
  const bool both_ways = kind == GeometryKind::Spherical && table.cutoff > M_PI;
  double sum = 0;
  for (uint32_t j = 0; j < e.image_count; ++j) {
    const auto& c = table.images[e.image_begin + j].center;
    for (const double sign : {1.0, -1.0}) {
      if (sign < 0 && !e.antipodal_pairs) continue;
      const Vec4 centre = sign * Vec4{c[0], c[1], c[2], c[3]};
      const double spread = model::area_factor_between(kind, x, centre);
      const double along = model::inner(kind, centre - x, normal);  // cos sqrt(A)
      sum += std::max(along, 0.0) / (spread * std::sqrt(spread));
      if (both_ways) sum += std::max(-along, 0.0) / (spread * std::sqrt(spread));
    }
  }
  const double expected = 0.5 / M_PI * sum;
  Renderer renderer(device(), scene);
  renderer.add_samples(512);
  EXPECT_NEAR(luminance_of(mean(renderer.image())), expected, 0.02 * expected)
      << geometry << " " << manifold << ", " << e.image_count << " images, " << light_samples
      << " light samples";
  EXPECT_EQ(renderer.non_finite_samples(), 0u);
}

// Exponential coordinates of a point `way` of the way from the cell's centre to the face that
// faces +z most, along a direction 17 degrees off the face's normal (S3: gnomonic chart
// distance tan d). The image of a light there just past the opposite face is nearly as near
// the patch at the centre as the light itself: the choice among images must give both their
// share, whichever the order it walks them in. (Along the normal itself, the lens's axis or a screw
// axis of the Poincare space, the long way round passes the centres of the cells, where the
// patch's copies would hide the light.)
Vec3 near_the_top_face(const std::string& manifold, double way) {
  const Scene scene = scene_from_json(R"({"geometry": "spherical", "manifold": )" + manifold + R"(,
    "camera": {"position": [0, 0, 0.05], "look_at": [0, 0, 0]}, "objects": []})");
  const DomainFace* top = &scene.manifold.faces.at(0);
  for (const DomainFace& face : scene.manifold.faces)
    if (face.normal.z > top->normal.z) top = &face;
  const Vec3 n = top->normal;
  const Vec3 u = normalize(n + 0.3 * normalize(cross(n, Vec3{1, 0, 0})));
  return u * std::atan(way * top->delta / dot(u, n));
}

// In S3 both ways round where the group lacks the antipodal map (L(11, 3)); where it holds it
// (the Poincare space) the long way round meets the patch's own copy at the antipode, and
// light sampling leaves it out, but every copy of the light is reached the short way: its 120
// images as 60 antipodal pairs (server/render/prepare/emitters.cpp).
TEST(PointLight, ItsImagesInAQuotientSumToTheirClosedForm) {
  expect_point_light_images_sum("euclidean", R"({"type": "torus", "size": 1.5})", {0.3, -0.2, 0.4}, 4);
  expect_point_light_images_sum("spherical", R"({"type": "lens", "p": 11, "q": 3, "max_crossings": 48})",
                                {0.1, 0.05, 0.15}, 2 * M_PI);
  expect_point_light_images_sum("spherical", R"({"type": "poincare-dodecahedral", "max_crossings": 48})",
                                {0.1, 0.05, 0.15}, 2 * M_PI);
  for (const char* manifold : {R"({"type": "lens", "p": 11, "q": 3, "max_crossings": 48})",
                               R"({"type": "poincare-dodecahedral", "max_crossings": 48})"})
    for (const double way : {0.3, 0.6, 0.9})
      expect_point_light_images_sum("spherical", manifold, near_the_top_face(manifold, way),
                                    2 * M_PI);
}

// Several light samples per vertex share one walk over the images (chooseImages: systematic
// sampling at (k + u) / n of their running weight). Here every image's share of the closed form
// is in proportion to its weight, so this holds each sample's reported probability to the image
// it took (an odd count, an even one and the most the frame allows; the light near a face,
// where two images weigh nearly the same). That the choices follow the weights is held by
// Mis.SeveralLightSamplesPerVertexStayUnbiased, where they do not.
TEST(PointLight, SeveralSamplesPerVertexSumItsImagesToTheirClosedForm) {
  const char* lens = R"({"type": "lens", "p": 11, "q": 3, "max_crossings": 48})";
  const char* poincare = R"({"type": "poincare-dodecahedral", "max_crossings": 48})";
  for (const int samples : {3, 4, kMaxLightSamples}) {
    expect_point_light_images_sum("spherical", lens, {0.1, 0.05, 0.15}, 2 * M_PI, samples);
    expect_point_light_images_sum("spherical", poincare, near_the_top_face(poincare, 0.9),
                                  2 * M_PI, samples);
  }
  expect_point_light_images_sum("euclidean", R"({"type": "torus", "size": 1.5})", {0.3, -0.2, 0.4},
                                4, 5);
}

// The same scene lit by area lights, rendered with light sampling + BSDF sampling (MIS) and
// with BSDF sampling alone: equal within the noise both report.
void expect_mis_matches_bsdf_sampling(Scene scene, uint32_t spp) {
  scene.render.lighting = LightingModel::Physical;
  scene.render.width = std::min(scene.render.width, 48);
  scene.render.height = std::min(scene.render.height, 48);
  Renderer mis(device(), scene);
  mis.add_samples(spp);
  scene.render.light_sampling = LightSampling::Bsdf;
  Renderer bsdf(device(), scene);
  bsdf.add_samples(spp);
  const Image a = mis.image(), b = bsdf.image();
  const double mean_a = luminance_of(mean(a)), mean_b = luminance_of(mean(b));
  EXPECT_GT(mean_a, 0.01) << scene.name;
  // The image means: far less noisy than single pixels, so a tight bound.
  EXPECT_NEAR(mean_a, mean_b, 0.03 * mean_b) << scene.name;
  // Per pixel: independent unbiased estimates differ by what their noise explains, i.e. their
  // relative RMS difference is about the two estimated errors added in quadrature.
  const double noise = std::hypot(mis.estimated_error(), bsdf.estimated_error());
  EXPECT_LT(relative_rms_difference(a, b), 1.5 * noise) << scene.name;
  EXPECT_LT(mis.estimated_error(), bsdf.estimated_error()) << scene.name;
  EXPECT_EQ(mis.non_finite_samples() + bsdf.non_finite_samples(), 0u);
}

TEST(Mis, AgreesWithBsdfSamplingInEveryGeometry) {
  for (const char* name : {"hyperbolic-lamps.json", "spherical-lamps.json", "torus-lamps.json"})
    expect_mis_matches_bsdf_sampling(load_scene_file(source_path("scenes/") / name), 64);
}

// Light sampling chooses among an emitter's images (shaders/lights/emitters.glsl, the running
// sum inverted at one uniform): in L(11, 3) with the cutoff past pi, 11 images each reached
// both ways round; in the Poincare dodecahedral space 64 images, the short way only (the group
// holds the antipodal map, and BSDF sampling, which finds whatever the long way would bring,
// agrees). Light sampling alone and MIS each converge to what BSDF sampling finds.
void expect_many_images_unbiased(const std::string& manifold, int light_samples = 1) {
  const Scene scene = scene_from_json(R"({"geometry": "spherical", "manifold": )" + manifold + R"(,
    "camera": {"position": [0.05, 0.03, 0.24], "look_at": [0, 0, 0], "fov_y": 80},
    "materials": {"teal": {"diffuse": [0.1, 0.6, 0.6]}, "lamp": {"emission": 4},
                  "gold": {"diffuse": [0.85, 0.7, 0.35]}},
    "objects": [{"type": "sphere", "material": "teal", "center": [0, 0, 0], "radius": 0.1},
                {"type": "sphere", "material": "lamp", "center": [0.05, 0.12, 0.1], "radius": 0.04},
                {"type": "domain_edges", "material": "gold", "radius": 0.006}],
    "render": {"width": 48, "height": 48, "max_depth": 2, "light_cutoff": 4,
               "light_samples": )" + std::to_string(light_samples) + "}}");
  ASSERT_GT(scene.render.light_cutoff, std::acos(-1.0));
  expect_mis_matches_bsdf_sampling(scene, 128);
  Scene light_alone = scene;
  light_alone.render.light_sampling = LightSampling::Light;
  expect_mis_matches_bsdf_sampling(light_alone, 128);
}

TEST(Mis, ChoosesAmongManyImagesWithoutBias) {
  expect_many_images_unbiased(R"({"type": "lens", "p": 11, "q": 3, "max_crossings": 24})");
  expect_many_images_unbiased(R"({"type": "poincare-dodecahedral", "max_crossings": 24})");
}

// With n light samples per vertex the light strategy counts n times in the power heuristic
// (n p_light against p_bsdf), at the light samples and at emitters that BSDF samples find: MIS
// still converges to BSDF sampling's image, and light sampling alone (no weights) as well.
TEST(Mis, SeveralLightSamplesPerVertexStayUnbiased) {
  expect_many_images_unbiased(R"({"type": "lens", "p": 11, "q": 3, "max_crossings": 24})", 3);
  expect_many_images_unbiased(R"({"type": "poincare-dodecahedral", "max_crossings": 24})", 4);
  Scene lamps = load_scene_file(source_path("scenes/torus-lamps.json"));
  lamps.render.light_samples = 4;
  expect_mis_matches_bsdf_sampling(lamps, 64);
}

// The bundled Poincare sphere, whose light has 60 pairs of images: at equal samples per pixel
// four light samples per vertex leave less noise than one, and the two images agree within
// that noise (the same estimate of the same image).
TEST(Mis, SeveralLightSamplesLowerThePoincareSpheresNoise) {
  Scene scene = load_scene_file(source_path("scenes/poincare-sphere.json"));
  scene.render.width = scene.render.height = 64;
  scene.render.light_samples = 1;
  Renderer one(device(), scene);
  one.add_samples(32);
  scene.render.light_samples = 4;
  Renderer four(device(), scene);
  four.add_samples(32);
  EXPECT_LT(four.estimated_error(), 0.8 * one.estimated_error());
  const double noise = std::hypot(one.estimated_error(), four.estimated_error());
  EXPECT_LT(relative_rms_difference(one.image(), four.image()), 1.5 * noise);
  EXPECT_NEAR(luminance_of(mean(four.image())), luminance_of(mean(one.image())),
              0.03 * luminance_of(mean(one.image())));
  EXPECT_EQ(one.non_finite_samples() + four.non_finite_samples(), 0u);
}

}  // namespace
}  // namespace geodesic::test
