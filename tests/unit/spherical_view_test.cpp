// What the default scene of a spherical space allows for (scene/spherical_view.h): the light's
// irradiance summed over its images and both ways round, and the camera's antipode kept clear.
#include "scene/spherical_view.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/catalogue.h"
#include "scene/default_scene.h"
#include "scene/dirichlet_domain.h"
#include "test_constants.h"

namespace geodesic {
namespace {

using test::kS3;

Mat4 antipodal_map() {
  Mat4 m = Mat4::identity();
  for (int i = 0; i < 4; ++i) m.m[i][i] = -1;
  return m;
}

// In projective space, S3 / {1, -1}, the light's image -L is its own long way round: listing
// the group whole or not, a point at distance d gets 1 / sin^2 d from the short way and as
// much from the long way (distance 2 pi - d, or pi - d to -L).
TEST(SphericalView, TheLongWayRoundIsTheAntipodalImageCountedOnce) {
  const Vec4 light = model::exp_origin(kS3, {0.3, 0.2, 0.1});
  const Vec4 p = model::exp_origin(kS3, {-0.4, 0.5, 0.2});
  const double s = std::sin(model::geodesic_distance(kS3, p, light));
  EXPECT_NEAR(orbit_irradiance({Mat4::identity()}, light, p), 2 / (s * s), 1e-12);
  EXPECT_NEAR(orbit_irradiance({Mat4::identity(), antipodal_map()}, light, p), 2 / (s * s), 1e-12);
}

// The group of the binary icosahedral space is listed whole (its order, 120), and the light's
// 120 images bring the spheres far more than its nearest image does: 1 / sin^2 of the nearest
// distance is a lower bound, and the rest is at least 119 times the least term, 1.
TEST(SphericalView, TheWholeGroupIsListedAndEveryImageShines) {
  const CatalogueEntry& e = *find_catalogue_entry("binary-icosahedral");
  const DirichletDomain d = dirichlet_domain(e.kind, e.generators);
  const std::vector<Mat4> group = spherical_group(d.manifold);
  ASSERT_EQ(group.size(), 120u);
  const Vec4 light = model::exp_origin(kS3, Vec3{0.1, 0.6, 0.2} * d.inradius);
  const Vec4 p = model::exp_origin(kS3, Vec3{0.5, 0.1, -0.85} * (0.55 * d.inradius));
  const double s = std::sin(model::geodesic_distance(kS3, p, light));
  EXPECT_GT(orbit_irradiance(group, light, p), 1 / (s * s) + 119);
}

// L(5,2)'s domain has an edge through the antipode of its centre, so every geodesic from a
// camera there ends on that edge's tube; the default scene's camera sits where the antipode
// and its images stay clear of edges and spheres by a tenth of the in-radius.
TEST(SphericalView, TheDefaultCameraKeepsItsAntipodeOffTheEdges) {
  const CatalogueEntry& e = *find_catalogue_entry("lens-5-2");
  const DirichletDomain d = dirichlet_domain(e.kind, e.generators);
  const std::vector<Mat4> group = spherical_group(d.manifold);
  ASSERT_EQ(group.size(), 5u);
  const double r = d.inradius, tube = 0.02 * r;
  EXPECT_LT(antipode_clearance(group, d.manifold.domain, tube, {}, model::origin()), 1e-3 * r);
  const auto doc = default_scene_document(e.title, e.kind, {{"type", "generators"}}, d);
  const auto& at = doc["camera"]["position"];
  const Vec4 eye = model::exp_origin(kS3, {at[0].get<double>(), at[1].get<double>(), at[2].get<double>()});
  EXPECT_GT(model::geodesic_distance(kS3, eye, model::origin()), 0.2 * r);
  EXPECT_GE(antipode_clearance(group, d.manifold.domain, tube, {}, eye), 0.1 * r);
  // Spaces whose centre's antipode is clear keep the camera at the centre.
  const CatalogueEntry& l73 = *find_catalogue_entry("lens-7-3");
  const DirichletDomain d73 = dirichlet_domain(l73.kind, l73.generators);
  EXPECT_EQ(default_scene_document(l73.title, l73.kind, {{"type", "generators"}}, d73)["camera"]["position"],
            nlohmann::ordered_json::array({0.0, 0.0, 0.0}));
}

}  // namespace
}  // namespace geodesic
