// Cusped hyperbolic manifolds rendered (scene/cusp_neighbourhoods.h): the figure-eight knot
// complement and the Whitehead link complement against H3 itself holding the group's copies of
// their spheres and cusp horoballs, and their default scenes' geodesics ending on a horosphere
// or an object rather than at the crossing cap. (The horosphere's angular size against its
// closed form is in horosphere_test.cpp; depth 64 without NaN in manifold_render_test.cpp's
// bundled-scene sweep.)
#include <array>
#include <cmath>
#include <map>

#include "common/shape_kinds.h"
#include "render/prepare/emitters.h"
#include "render_fixture.h"
#include "scene/catalogue.h"
#include "scene/cusp_neighbourhoods.h"
#include "scene/dirichlet_domain.h"
#include "test_constants.h"

namespace geodesic::test {
namespace {


// Glowing spheres near the origin and a glowing horosphere per ideal vertex (one colour per
// cusp), the camera at the origin, primary rays only.
Scene glowing_cusped(const DirichletDomain& domain) {
  Scene scene;
  scene.name = "cusped";
  scene.geometry = kH3;
  scene.manifold = domain.manifold;
  scene.manifold.max_crossings = 64;
  const Vec3 colours[] = {{1, 0.3, 0.1}, {0.2, 1, 0.3}, {0.2, 0.4, 1}, {0.5, 0.5, 0.5}, {0.9, 0.8, 0.2}};
  for (int i = 0; i < 5; ++i) {
    Material glow;
    glow.name = "glow" + std::to_string(i);
    glow.emission = colours[i];
    scene.materials.push_back(glow);
  }
  const Vec3 places[] = {{0.6, 0.2, -0.7}, {-0.5, 0.6, 0.4}, {0.1, -0.8, 0.3}};
  for (int i = 0; i < 3; ++i)
    scene.spheres.push_back(
        {normalize(places[i]) * (0.55 * domain.inradius), 0.3 * domain.inradius, uint32_t(i)});
  for (const CuspHorosphere& h : cusp_horospheres(domain.manifold)) {
    ShapeParams params;
    params.a = std::exp(h.distance) * Vec4(h.direction, 1);
    scene.shapes.push_back({SHAPE_HOROSPHERE, params, uint32_t(3 + h.cusp % 2)});
  }
  scene.camera.pose = model::rotation(normalize(Vec3{0.3, 1, 0.2}), 0.9);
  scene.camera.fov_y_degrees = 100;
  scene.render.width = scene.render.height = 96;
  scene.render.max_depth = 0;
  return scene;
}

// The group elements that are words of at most `length` face pairings, one per element (its
// image of the origin, which no element fixes, tells them apart).
std::vector<Mat4> words_up_to(const Manifold& m, int length) {
  std::map<std::array<long long, 3>, bool> seen;
  auto key = [](const Mat4& g) {
    const Vec4 o = g * model::origin();
    return std::array<long long, 3>{std::llround(o.x * 1e6), std::llround(o.y * 1e6), std::llround(o.z * 1e6)};
  };
  std::vector<Mat4> elements{Mat4::identity()};
  seen[key(elements[0])] = true;
  std::size_t begin = 0;
  for (int k = 0; k < length; ++k) {
    const std::size_t end = elements.size();
    for (std::size_t i = begin; i < end; ++i)
      for (const DomainFace& f : m.faces) {
        const Mat4 g = model::reorthonormalize(kH3, elements[i] * f.pairing);
        if (seen.emplace(key(g), true).second) elements.push_back(g);
      }
    begin = end;
  }
  return elements;
}

// The quotient, its geodesics cut off after `crossings` face crossings, against the cover
// holding g(object) for every g that is a word of at most that many pairings. A geodesic of the
// quotient that meets an object after crossing faces f1 ... fk meets, in the cover, the copy by
// g_f1 ... g_fk, and nothing nearer (the quotient's first hit is the true first hit): wherever
// the quotient's pixel is lit, the cover's must match it. (The cover's extra copies light some
// pixels the quotient cut off.)
void expect_quotient_matches_cover(const std::string& name, int crossings) {
  SCOPED_TRACE(name);
  const CatalogueEntry& e = *find_catalogue_entry(name);
  const DirichletDomain domain = dirichlet_domain(kH3, e.generators);
  Scene quotient = glowing_cusped(domain);
  quotient.manifold.max_crossings = crossings;
  Scene cover = quotient;
  cover.manifold = Manifold{};
  cover.spheres.clear();
  cover.shapes.clear();
  const std::vector<Mat4> elements = words_up_to(domain.manifold, crossings);
  for (const Mat4& g : elements) {
    for (const Sphere& s : quotient.spheres)
      cover.spheres.push_back(
          {model::log_origin(kH3, g * model::exp_origin(kH3, s.center)), s.radius, s.material});
    for (Shape s : quotient.shapes) {
      s.params.a = g * s.params.a;  // the horoball {<x, l> > -1} moved: l -> g l
      cover.shapes.push_back(s);
    }
  }
  // One sample per pixel: a pixel of the quotient is then wholly lit or wholly cut off, and its
  // one geodesic is the cover's (the same seed draws the same pixel position).
  Renderer renderer(device(), quotient);
  renderer.add_samples(1);
  const Image a = renderer.image(), b = render(cover, 1);
  const PixelAgreement agreement = compare_pixels(a, b, a);
  const int lit = agreement.lit, differing = agreement.differing_lit;
  const int pixels = a.width * a.height;
  EXPECT_GT(lit, pixels * 3 / 5) << "most geodesics should end on an object or a horosphere";
  // Only where float round-off moves a silhouette by a fraction of a pixel.
  EXPECT_LE(differing, lit / 100) << differing << " of " << lit << " lit pixels differ ("
                                  << elements.size() << " elements)";
  EXPECT_EQ(renderer.non_finite_samples(), 0u);
}

TEST(CuspedQuotient, FigureEightLooksLikeItsCover) { expect_quotient_matches_cover("figure-eight", 3); }

TEST(CuspedQuotient, WhiteheadLinkLooksLikeItsCover) {
  expect_quotient_matches_cover("whitehead-link", 3);
}

// The catalogue's default scenes of the cusped spaces, at depth 3: under 1 % of pixels hold a
// geodesic cut off at max_crossings (most hold none), and no sample is NaN or infinite.
TEST(CuspedQuotient, DefaultScenesEndTheirGeodesicsOnHorospheres) {
  for (const char* name : {"figure-eight", "figure-eight-sister", "gieseking", "whitehead-link"}) {
    SCOPED_TRACE(name);
    Scene scene = load_scene_file(source_path(std::string("scenes/catalogue/") + name + ".json"));
    scene.render.width = scene.render.height = 64;
    scene.render.max_depth = 3;
    Renderer renderer(device(), scene);
    renderer.add_samples(4);
    const uint64_t paths = 64 * 64 * 4;
    EXPECT_LT(renderer.trace_counters().truncated_rays, paths / 100);
    EXPECT_EQ(renderer.non_finite_samples(), 0u);
  }
}

// The camera on a face of the figure-eight's domain and on one of its finite vertices (seams
// the camera's placement carries into the domain), looking up the cusp: finite samples, light,
// and geodesics that end on a horosphere or an object, not at the crossing cap.
TEST(CuspedQuotient, CamerasOnAFaceAndAVertex) {
  Scene scene = load_scene_file(source_path("scenes/catalogue/figure-eight.json"));
  scene.render.width = scene.render.height = 48;
  scene.render.max_depth = 3;
  const Polyhedron& domain = scene.manifold.domain;
  int finite = 0;
  while (ideal_vertex(kH3, domain.vertices.at(finite))) ++finite;
  const Vec3 face = scene.manifold.faces[0].normal * scene.manifold.faces[0].delta;
  const Vec3 vertex = domain.vertices[finite];
  for (const Vec3& chart : {face, vertex}) {
    SCOPED_TRACE(chart.x);
    const Vec3 exponential = normalize(chart) * std::atanh(length(chart));
    scene.camera.pose = model::translation(kH3, exponential) * model::rotation({1, 0, 0}, 0.4);
    Renderer renderer(device(), scene);
    renderer.add_samples(4);
    EXPECT_EQ(renderer.non_finite_samples(), 0u);
    EXPECT_LT(renderer.trace_counters().truncated_rays, 48u * 48 * 4 / 100);
    EXPECT_GT(luminance_of(mean(renderer.image())), 0.05);
  }
}

// The cusps' sky as the only light, in the four cusped spaces of the catalogue (the figure-
// eight, its sister and Gieseking have two ideal vertices in one cusp, the Whitehead link one
// in each of two): diffuse spheres under diffuse, glowing horospheres. Light
// sampling picks among each cusp's horoballs near the cell (one emitter per cusp, however many
// ideal vertices it has: render/prepare/emitters.h), and MIS and BSDF sampling alone agree, in
// the whole image within 1.5 % and in each 8x8 block within 4 % (their noise is a third of
// that). Before the path went on past its last bounce for the horoballs past the cutoff
// (PipelineFeatures::unsampled_emission), MIS came out 5 % darker.
TEST(CuspedQuotient, TheSkyIsSampledAsALight) {
  for (const char* name : {"figure-eight", "figure-eight-sister", "gieseking", "whitehead-link"}) {
    SCOPED_TRACE(name);
    const DirichletDomain domain = dirichlet_domain(kH3, find_catalogue_entry(name)->generators);
    Scene scene = glowing_cusped(domain);
    for (int i = 0; i < 3; ++i) {
      scene.materials[i].emission = Vec3{};
      scene.materials[i].diffuse = Vec3{0.7, 0.7, 0.7};
    }
    for (int i = 3; i < 5; ++i) scene.materials[i].diffuse = Vec3{0.4, 0.4, 0.4};
    scene.render.width = scene.render.height = 32;
    scene.render.max_depth = 2;

    const EmitterTable table = build_emitters(scene);
    ASSERT_EQ(table.emitters.size(), std::size_t(domain.cusps));
    for (const GpuEmitter& e : table.emitters) {
      EXPECT_EQ(e.kind, uint32_t(EmitterKind::Horosphere));
      EXPECT_GE(e.image_count, 1u);
    }
    for (std::size_t i = 0; i < scene.shapes.size(); ++i)
      EXPECT_EQ(table.shape_emitter[i], scene.shapes[i].material - 3) << "shape " << i;

    Image images[2];
    for (LightSampling sampling : {LightSampling::Mis, LightSampling::Bsdf}) {
      scene.render.light_sampling = sampling;
      Renderer renderer(device(), scene);
      renderer.add_samples(256);
      EXPECT_EQ(renderer.non_finite_samples(), 0u);
      images[sampling == LightSampling::Mis ? 0 : 1] = renderer.image();
    }
    const Image &mis = images[0], &bsdf = images[1];
    const double whole = luminance_of(mean(bsdf));
    EXPECT_NEAR(luminance_of(mean(mis)), whole, 0.015 * whole);
    for (int y = 0; y < 32; y += 8)
      for (int x = 0; x < 32; x += 8) {
        const double block = luminance_of(mean(bsdf, x, y, x + 8, y + 8));
        EXPECT_NEAR(luminance_of(mean(mis, x, y, x + 8, y + 8)), block, 0.04 * block)
            << "block at " << x << ", " << y;
      }
  }
}

}  // namespace
}  // namespace geodesic::test
