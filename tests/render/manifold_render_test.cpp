// Curved spaces and quotient manifolds, rendered: what the double-precision reference says
// must appear where, in every geometry.
#include <cmath>
#include <numbers>

#include "render_fixture.h"

namespace geodesic::test {
namespace {

// A scene with one emissive marker sphere, no lights, and the camera at the origin looking
// along the unit direction `view` (a tangent at the origin).
Scene marker_scene(GeometryKind kind, Manifold manifold, const Vec3& marker, double radius,
                   const Vec3& view, double fov_degrees, int size) {
  Scene scene;
  scene.name = "marker";
  scene.geometry = kind;
  scene.manifold = std::move(manifold);
  Material glow;
  glow.name = "glow";
  glow.emission = {1.0, 0.5, 0.25};
  scene.materials.push_back(glow);
  scene.spheres.push_back({marker, radius, 0});
  const Vec3 back = -normalize(view);
  const Vec3 helper = std::abs(back.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
  const Vec3 right = normalize(cross(helper, back));
  const Vec3 up = cross(back, right);
  Mat4 pose = Mat4::identity();
  for (int r = 0; r < 3; ++r) {
    pose.m[r][0] = right[r];
    pose.m[r][1] = up[r];
    pose.m[r][2] = back[r];
  }
  scene.camera.pose = pose;
  scene.camera.fov_y_degrees = fov_degrees;
  scene.render.width = scene.render.height = size;
  scene.render.max_depth = 0;
  return scene;
}

// For every face of a bundled manifold, the copy of a marker seen through that face appears
// exactly where the reference puts it: in the direction of g^-1(marker) from the origin.
void expect_copies_through_faces(GeometryKind kind, const Manifold& manifold) {
  const Vec4 origin = model::origin();
  for (size_t f = 0; f < manifold.faces.size(); ++f) {
    const DomainFace& face = manifold.faces[f];
    const DomainFace& partner = manifold.faces[face.partner];
    // The marker sits inside the domain near the partner face (off its axis, so that for a
    // mirror the marker itself does not block the view of its reflection).
    const Vec3 tilt = normalize(cross(partner.normal, Vec3(0.3, 0.5, 0.7)));
    const Vec3 toward = normalize(partner.normal + 0.25 * tilt);
    const double inradius = model::geodesic_distance(kind, origin, model::lift(kind, partner.normal * partner.delta));
    const Vec3 marker = toward * (0.7 * inradius);
    const Vec4 copy = model::inverse_isometry(kind, face.pairing) * model::exp_origin(kind, marker);
    const Vec3 view = model::geodesic_direction(kind, origin, copy).xyz();
    const Scene scene = marker_scene(kind, manifold, marker, 0.05 * inradius, view, 2.0, 9);
    const Image image = render(scene, 1);
    EXPECT_NEAR(image.at(4, 4, 0), 1.0, 1e-3) << manifold.name << " face " << f;
    EXPECT_NEAR(image.at(4, 4, 1), 0.5, 1e-3) << manifold.name << " face " << f;
  }
}

TEST(Manifolds, TorusShowsTheCellCopiedAcrossEveryFace) {
  expect_copies_through_faces(GeometryKind::Euclidean, make_torus(GeometryKind::Euclidean, 1.5));
}

TEST(Manifolds, MirroredDodecahedronReflectsInEveryFace) {
  expect_copies_through_faces(GeometryKind::Hyperbolic, make_mirrored_dodecahedron());
}

TEST(Manifolds, PoincareSpaceGluesOppositeFacesWithATenthTurn) {
  expect_copies_through_faces(GeometryKind::Spherical, make_poincare_dodecahedral_space());
}

TEST(Manifolds, SeifertWeberSpaceGluesOppositeFacesWithThreeTenthsTurn) {
  expect_copies_through_faces(GeometryKind::Hyperbolic, make_seifert_weber_space());
}

// In S3 a geodesic closes after 2 pi: a marker just behind the camera is seen straight ahead,
// after the ray has gone all the way around (through the chart atlas' cells).
TEST(CurvedSpaces, SphericalSpaceShowsWhatIsBehindYouAllTheWayAround) {
  const Scene s3 = marker_scene(GeometryKind::Spherical, {}, {0, 0, 0.5}, 0.1, {0, 0, -1}, 2, 9);
  const Image around = render(s3, 1);
  EXPECT_NEAR(around.at(4, 4, 0), 1.0, 1e-3);
  // Flat space has no way around.
  const Scene e3 = marker_scene(GeometryKind::Euclidean, {}, {0, 0, 0.5}, 0.1, {0, 0, -1}, 2, 9);
  EXPECT_EQ(render(e3, 1).at(4, 4, 0), 0.0f);
}

// Every geodesic of S3 closes after one turn, and so does its image in a quotient: tracing
// stops there (a hit at t + 2 pi is one at t) instead of at the crossing cap. In the Poincare
// space and L(7, 3) at their own caps almost no geodesic is cut off (before the stop at one
// turn, 11 % and 29 % of paths ran into the cap), and raising the cap to 64 changes at most
// 0.1 % of pixels.
TEST(CurvedSpaces, SphericalQuotientsEndGeodesicsAfterOneTurn) {
  for (const char* file : {"scenes/poincare-sphere.json", "scenes/catalogue/lens-7-3.json"}) {
    SCOPED_TRACE(file);
    Scene scene = load_scene_file(source_path(file));
    scene.render.width = scene.render.height = 64;
    Renderer own(device(), scene);
    own.add_samples(4);
    EXPECT_LT(own.trace_counters().truncated_rays, 64u * 64 * 4 / 1000);
    scene.manifold.max_crossings = 64;
    Renderer raised(device(), scene);
    raised.add_samples(4);
    const Image a = own.image(), b = raised.image();
    int differing = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x)
        for (int c = 0; c < 3; ++c)
          if (std::abs(a.at(x, y, c) - b.at(x, y, c)) > 1e-6) {
            ++differing;
            break;
          }
    EXPECT_LE(differing, 64 * 64 / 1000);
  }
}

// A sphere of radius r at distance d subtends an angular radius alpha with sin(alpha) =
// r / d (E3), sinh r / sinh d (H3), sin r / sin d (S3).
TEST(CurvedSpaces, SphereAngularSizeFollowsEachGeometry) {
  struct Case {
    GeometryKind kind;
    double radius, distance, sin_alpha;
  };
  const Case cases[] = {
      {GeometryKind::Euclidean, 0.5, 2.0, 0.5 / 2.0},
      {GeometryKind::Hyperbolic, 0.5, 2.0, std::sinh(0.5) / std::sinh(2.0)},
      // Past pi/2 spheres grow again as they recede: this one looks bigger than the next.
      {GeometryKind::Spherical, 0.3, 2.2, std::sin(0.3) / std::sin(2.2)},
      {GeometryKind::Spherical, 0.3, 1.0, std::sin(0.3) / std::sin(1.0)},
  };
  constexpr int kSize = 101;
  constexpr double kFov = 60;
  for (const Case& c : cases) {
    const Scene scene =
        marker_scene(c.kind, {}, {0, 0, -c.distance}, c.radius, {0, 0, -1}, kFov, kSize);
    const Image image = render(scene, 16);
    // Covered fraction of the centre row, in pixels, against the pinhole projection of alpha.
    double covered = 0;
    for (int x = 0; x < kSize; ++x) covered += image.at(x, kSize / 2, 0);
    const double alpha = std::asin(c.sin_alpha);
    const double tan_half = std::tan(kFov * std::numbers::pi / 360);
    const double expected = std::tan(alpha) / tan_half * kSize;
    EXPECT_NEAR(covered, expected, 1.0) << geometry_name(c.kind) << " r " << c.radius << " d "
                                        << c.distance;
  }
}

// Every bundled scene, at depth 64: no sample is NaN or infinite, no pixel either.
TEST(CurvedSpaces, NoBundledSceneProducesNonFiniteSamplesAtDepth64) {
  for (const auto& entry : std::filesystem::directory_iterator(source_path("scenes"))) {
    if (entry.path().extension() != ".json") continue;
    Scene scene = load_scene_file(entry.path());
    scene.render.width = scene.render.height = 16;
    scene.render.max_depth = 64;
    Renderer renderer(device(), scene);
    renderer.add_samples(2);
    EXPECT_EQ(renderer.non_finite_samples(), 0u) << entry.path();
    for (float v : renderer.image().rgb) ASSERT_TRUE(std::isfinite(v)) << entry.path();
  }
}

}  // namespace
}  // namespace geodesic::test

namespace geodesic::test {
namespace {

// Seams: rays straight through a face centre, an edge and a vertex of the domain. Each wall of
// the mirrored right-angled dodecahedron is a mirror, so a face, an edge (two perpendicular
// mirrors) and a vertex (three: a corner reflector) all send the ray straight back: a marker
// behind the camera must fill the centre pixel, with nothing leaking through the seam.
TEST(Seams, RaysThroughFacesEdgesAndVerticesOfTheMirroredDodecahedronComeStraightBack) {
  const Manifold manifold = make_mirrored_dodecahedron();
  const Polyhedron& domain = manifold.domain;
  const auto& edge = domain.edges.at(0);
  const Vec3 targets[] = {manifold.faces[0].normal * manifold.faces[0].delta,
                          (domain.vertices[edge[0]] + domain.vertices[edge[1]]) / 2,
                          domain.vertices.at(0)};
  const char* names[] = {"face", "edge", "vertex"};
  for (int i = 0; i < 3; ++i) {
    const Vec3 view = normalize(targets[i]);
    const Scene scene =
        marker_scene(GeometryKind::Hyperbolic, manifold, view * -0.4, 0.05, view, 2.0, 9);
    Renderer renderer(device(), scene);
    renderer.add_samples(1);
    const Image image = renderer.image();
    EXPECT_NEAR(image.at(4, 4, 0), 1.0, 1e-3) << names[i];
    EXPECT_EQ(renderer.non_finite_samples(), 0u) << names[i];
  }
}

// In the 3-torus a ray through a corner of the cube continues into the diagonal copy, and a
// ray lying in a face plane slides along it to the next face.
TEST(Seams, TorusRaysThroughACornerAndAlongAFace) {
  const double h = 1.5;
  const Manifold torus = make_torus(GeometryKind::Euclidean, h);
  const Vec3 diagonal = normalize(Vec3(1, 1, 1));
  Scene corner = marker_scene(GeometryKind::Euclidean, torus, diagonal * -0.5, 0.1, diagonal, 2, 9);
  EXPECT_NEAR(render(corner, 1).at(4, 4, 0), 1.0, 1e-3) << "corner";

  // Starting on the face z = h and skimming down: 2.25 along x, 0.0675 down to the marker.
  Scene along = marker_scene(GeometryKind::Euclidean, torus, {-0.75, 0, h - 0.0675}, 0.05,
                             normalize(Vec3(1, 0, -0.03)), 0.5, 9);
  for (int r = 0; r < 3; ++r) along.camera.pose.m[r][3] = r == 2 ? h : 0;  // on the face z = h
  Renderer renderer(device(), along);
  renderer.add_samples(1);
  EXPECT_NEAR(renderer.image().at(4, 4, 0), 1.0, 1e-3) << "along the face";
  EXPECT_EQ(renderer.non_finite_samples(), 0u);
}

// A camera placed outside the domain is carried in by the face pairings, as a walking camera
// is: the image equals the one taken from the equivalent point inside.
TEST(Seams, CameraOutsideTheDomainIsCarriedBackIn) {
  const Manifold torus = make_torus(GeometryKind::Euclidean, 1.5);
  Scene inside = marker_scene(GeometryKind::Euclidean, torus, {0.5, 0.2, -0.6}, 0.3,
                              normalize(Vec3(0.3, 0.1, -1)), 60, 24);
  Scene outside = inside;
  for (int r = 0; r < 3; ++r) inside.camera.pose.m[r][3] = Vec3(-0.8, 0.3, 0.4)[r];
  for (int r = 0; r < 3; ++r) outside.camera.pose.m[r][3] = Vec3(-0.8 + 3 * 3, 0.3 - 3, 0.4)[r];
  EXPECT_LT(rms_difference(render(inside, 1), render(outside, 1)), 1e-4);
}

}  // namespace
}  // namespace geodesic::test
