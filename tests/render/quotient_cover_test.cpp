// A spherical quotient S3 / Gamma looks exactly like S3 itself holding every copy g(object),
// g in Gamma: the face crossings, chart pieces and gluings of the quotient's domain must add up
// to the plain geodesics of the cover. This checks a domain end to end, pixel by pixel,
// against a render that uses none of it.
#include <cmath>

#include "render_fixture.h"
#include "scene/catalogue.h"
#include "scene/dirichlet_domain.h"
#include "test_constants.h"

namespace geodesic::test {
namespace {


// Every element of the finite group the generators span (closure under products).
std::vector<Mat4> group_elements(const std::vector<Mat4>& generators) {
  auto same = [](const Mat4& a, const Mat4& b) {
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        if (std::abs(a.m[r][c] - b.m[r][c]) > 1e-9) return false;
    return true;
  };
  std::vector<Mat4> elements{Mat4::identity()};
  for (std::size_t i = 0; i < elements.size(); ++i)
    for (const Mat4& g : generators) {
      const Mat4 product = model::reorthonormalize(kS3, g * elements[i]);
      if (std::none_of(elements.begin(), elements.end(), [&](const Mat4& e) { return same(e, product); }))
        elements.push_back(product);
      if (elements.size() > 1000) throw std::runtime_error("not a finite group");
    }
  return elements;
}

// Three glowing spheres near the origin (inside the ball of radius `inradius`), the camera at
// the origin, primary rays only.
Scene glowing_spheres(double inradius) {
  Scene scene;
  scene.name = "cover";
  scene.geometry = kS3;
  const Vec3 colours[] = {{1, 0.3, 0.1}, {0.2, 1, 0.3}, {0.2, 0.4, 1}};
  const Vec3 places[] = {{0.6, 0.2, -0.7}, {-0.5, 0.6, 0.4}, {0.1, -0.8, 0.3}};
  for (int i = 0; i < 3; ++i) {
    Material glow;
    glow.name = "glow" + std::to_string(i);
    glow.emission = colours[i];
    scene.materials.push_back(glow);
    scene.spheres.push_back({normalize(places[i]) * (0.55 * inradius), 0.3 * inradius, uint32_t(i)});
  }
  scene.camera.pose = model::rotation(normalize(Vec3{0.3, 1, 0.2}), 0.7);
  scene.camera.fov_y_degrees = 100;
  scene.render.width = scene.render.height = 48;
  scene.render.max_depth = 0;
  return scene;
}

void expect_quotient_matches_cover(const std::string& name, const std::vector<Mat4>& generators) {
  SCOPED_TRACE(name);
  const DirichletDomain domain = dirichlet_domain(kS3, generators);
  Scene quotient = glowing_spheres(domain.inradius);
  quotient.manifold = domain.manifold;
  quotient.manifold.max_crossings = 64;  // a ray that misses everything goes all the way round

  Scene cover = quotient;
  cover.manifold = Manifold{};
  cover.spheres.clear();
  // Gamma from the generators themselves, conjugated as the domain was: its base point moved
  // to the origin.
  const Mat4 move = model::translation_from(kS3, model::exp_origin(kS3, domain.base_point));
  std::vector<Mat4> moved;
  for (const Mat4& g : generators) moved.push_back(move * g * model::inverse_isometry(kS3, move));
  const std::vector<Mat4> elements = group_elements(moved);
  ASSERT_EQ(elements.size(), domain.elements);
  for (const Mat4& g : elements)
    for (const Sphere& s : quotient.spheres)
      cover.spheres.push_back({model::log_origin(kS3, g * model::exp_origin(kS3, s.center)), s.radius, s.material});

  const Image a = render(quotient, 4), b = render(cover, 4);
  const PixelAgreement agreement = compare_pixels(a, b, b);
  const int lit = agreement.lit, differing = agreement.differing;
  const int pixels = a.width * a.height;
  EXPECT_GT(lit, pixels / 10) << "the copies should fill part of the view";
  EXPECT_LT(lit, pixels) << "and leave some background";
  // Only where float round-off moves a sphere's silhouette by a fraction of a pixel.
  EXPECT_LE(differing, pixels / 100) << differing << " of " << pixels << " pixels differ";
  EXPECT_LT(rms_difference(a, b), 0.02);
}

// Chart atlases: the mirrored lenses (mirror faces glued to themselves), L(5, 1) and L(3, 1)
// (lunes twisted by their pairings, the camera on the edge all their pieces share); one
// single-chart domain as a control.
TEST(QuotientCover, MirroredLensLooksLikeItsCover) {
  expect_quotient_matches_cover("mirrored lens 6", mirrored_lens_generators(6));
  expect_quotient_matches_cover("mirrored lens 4", mirrored_lens_generators(4));
}

// The antipodal map and two mirrors: the domain reaches the horizon, its bisector normals span
// more than a plane, so it is cut by Voronoi cells, two of whose walls are mirrors.
TEST(QuotientCover, VoronoiAtlasWithMirrorsLooksLikeItsCover) {
  Mat4 x_mirror = Mat4::identity(), y_mirror = Mat4::identity(), antipodal;
  x_mirror.m[0][0] = y_mirror.m[1][1] = -1;
  for (int i = 0; i < 4; ++i) antipodal.m[i][i] = -1;
  expect_quotient_matches_cover("-I and two mirrors", {antipodal, x_mirror, y_mirror});
}

TEST(QuotientCover, LensSpacesLookLikeTheirCover) {
  expect_quotient_matches_cover("L(5,1)", lens_space_generators(5, 1));
  expect_quotient_matches_cover("L(3,1)", lens_space_generators(3, 1));  // its arc cut in two
  expect_quotient_matches_cover("L(7,2)", lens_space_generators(7, 2));
}

// The tracer's device counters add up: with primary rays only and no lights, each pixel's
// geodesic is one segment plus one per face crossed (a geodesic cut off at max_crossings
// crossed its last face without tracing on), and exactly the pixels it cut off stay black.
TEST(QuotientCover, TraceCountersAccountForEverySegment) {
  for (const auto& [name, generators] :
       {std::pair{"L(7,2)", lens_space_generators(7, 2)},
        std::pair{"L(5,1)", lens_space_generators(5, 1)}}) {
    SCOPED_TRACE(name);
    const DirichletDomain domain = dirichlet_domain(kS3, generators);
    Scene quotient = glowing_spheres(domain.inradius);
    quotient.manifold = domain.manifold;
    quotient.manifold.max_crossings = 3;  // short: some geodesics are cut off
    Renderer renderer(device(), quotient);
    renderer.add_samples(1);
    const TraceCounters counters = renderer.trace_counters();
    const Image image = renderer.image();
    uint64_t black = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        black += image.at(x, y, 0) == 0 && image.at(x, y, 1) == 0 && image.at(x, y, 2) == 0;
    const uint64_t pixels = uint64_t(image.width) * image.height;
    EXPECT_GT(counters.crossed_faces, pixels / 2);
    EXPECT_GT(counters.truncated_rays, 0u);
    EXPECT_EQ(counters.truncated_rays, black);
    EXPECT_EQ(counters.traced_rays, pixels + counters.crossed_faces - counters.truncated_rays);
    renderer.reset();  // the counters start over with the accumulation
    EXPECT_EQ(renderer.trace_counters().crossed_faces, 0u);
    EXPECT_EQ(renderer.trace_counters().traced_rays, 0u);
  }
}

}  // namespace
}  // namespace geodesic::test
