// The bundled manifolds against their closed-form facts (dodecahedron radii, reflection
// entries, the binary icosahedral group, the 3/10 turn), edge cycles, rays crossing faces as in
// the paper's algorithm 1, and validation and loader errors on crafted bad input.
#include "scene/manifold.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "scene/manifold_loader.h"
#include "scene/scene.h"
#include "test_constants.h"

namespace geodesic {
namespace {

using model::chart;
using model::lift;
using test::kE3;
using test::kH3;
using test::kPi;
using test::kS3;
using test::max_difference;
constexpr double kPhi = std::numbers::phi;

double distance_from_identity(const Mat4& g) { return max_difference(g, Mat4::identity()); }

std::string scene_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(BundledManifolds, ValidateWithTheirFaceCounts) {
  const Manifold torus = make_torus(kE3, 1), mirrored = make_mirrored_dodecahedron(),
                 poincare = make_poincare_dodecahedral_space(), sw = make_seifert_weber_space();
  EXPECT_NO_THROW(validate_manifold(kE3, torus));
  EXPECT_NO_THROW(validate_manifold(kH3, mirrored));
  EXPECT_NO_THROW(validate_manifold(kS3, poincare));
  EXPECT_NO_THROW(validate_manifold(kH3, sw));
  EXPECT_EQ(torus.faces.size(), 6u);
  EXPECT_EQ(mirrored.faces.size(), 12u);
  EXPECT_EQ(poincare.faces.size(), 12u);
  EXPECT_EQ(sw.faces.size(), 12u);
  EXPECT_EQ(torus.domain.vertices.size(), 8u);
  EXPECT_EQ(sw.domain.vertices.size(), 20u);
  EXPECT_EQ(poincare.name, "poincare-dodecahedral");
  EXPECT_EQ(Manifold{}.name, "none");
  EXPECT_THROW(make_torus(kH3, 1), SceneError);
}

TEST(BundledManifolds, TorusGluesOppositeFacesByTranslations) {
  const Manifold m = make_torus(kE3, 1.5);
  for (std::size_t f = 0; f < 6; ++f) {
    const DomainFace& face = m.faces[f];
    EXPECT_EQ(length(m.faces[face.partner].normal + face.normal), 0);
    const Vec4 image = face.pairing * Vec4{face.normal * 1.5, 1};  // face centre
    EXPECT_NEAR(length(image.xyz() + face.normal * 1.5), 0, 1e-15);
  }
}

TEST(MirroredDodecahedron, MatchesTheClosedForms) {
  const Manifold m = make_mirrored_dodecahedron();
  const double k = std::pow(5.0, -0.25);
  int adjacent = 0;
  for (const DomainFace& a : m.faces) {
    EXPECT_NEAR(a.delta, k, 1e-15);
    EXPECT_NEAR(std::atanh(a.delta), 0.80846, 5e-6);  // in-radius
    EXPECT_NEAR(a.delta * a.delta, 1 / std::sqrt(5.0), 1e-15);  // tanh^2(in-radius)
    EXPECT_NEAR(a.pairing.m[3][3], kPhi * kPhi, 1e-12);  // cosh(2 in-radius)
    EXPECT_NEAR(distance_from_identity(a.pairing * a.pairing), 0, 1e-12);
    for (const DomainFace& b : m.faces) {
      const double c = dot(a.normal, b.normal);
      if (std::abs(c - 1 / std::sqrt(5.0)) < 1e-12) ++adjacent;
      EXPECT_TRUE(std::abs(std::abs(c) - 1 / std::sqrt(5.0)) < 1e-12 ||
                  std::abs(std::abs(c) - 1) < 1e-12);
    }
  }
  EXPECT_EQ(adjacent, 12 * 5);
  for (const Vec3& v : m.domain.vertices) {  // circum-radius: cosh = phi^2 / sqrt 2
    EXPECT_NEAR(std::atanh(length(v)), 1.22646, 5e-6);
    EXPECT_NEAR(std::cosh(std::atanh(length(v))), kPhi * kPhi / std::sqrt(2.0), 1e-12);
  }
  for (const auto& [a, b] : m.domain.edges) {  // mid-radius: cosh = phi
    const Vec3 mid = (m.domain.vertices[a] + m.domain.vertices[b]) / 2.0;
    EXPECT_NEAR(std::cosh(std::atanh(length(mid))), kPhi, 1e-12);
  }
  for (int e = 0; e < 30; ++e) EXPECT_NEAR(dihedral_angle(kH3, m, e), kPi / 2, 1e-12);
}

// Left multiplication by the unit quaternion (v, a) = a + v_x i + v_y j + v_z k, with the real
// part in w.
Mat4 left_multiplication(const Vec3& v, double a) {
  Mat4 q;
  const double rows[4][4] = {
      {a, -v.z, v.y, v.x}, {v.z, a, -v.x, v.y}, {-v.y, v.x, a, v.z}, {-v.x, -v.y, -v.z, a}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) q.m[i][j] = rows[i][j];
  return q;
}

TEST(PoincareDodecahedralSpace, PairingsAreTheBinaryIcosahedralGenerators) {
  const Manifold m = make_poincare_dodecahedral_space();
  for (const DomainFace& face : m.faces) {
    EXPECT_NEAR(face.delta, std::tan(kPi / 10), 1e-15);  // in-radius pi/10
    const Mat4 q = left_multiplication(-std::sin(kPi / 5) * face.normal, std::cos(kPi / 5));
    EXPECT_LT(max_difference(face.pairing, q), 1e-12);
    Mat4 power = Mat4::identity(), minus_one;
    for (int i = 0; i < 4; ++i) minus_one.m[i][i] = -1;
    for (int i = 1; i <= 10; ++i) {
      power = face.pairing * power;
      if (i == 5) {
        EXPECT_LT(max_difference(power, minus_one), 1e-12);  // g^5 = -1, the centre
      }
      if (i < 10) {
        EXPECT_GT(distance_from_identity(power), 0.1);
      }
    }
    EXPECT_LT(distance_from_identity(power), 1e-12);  // order exactly 10
  }
  for (int e = 0; e < 30; ++e) EXPECT_NEAR(dihedral_angle(kS3, m, e), 2 * kPi / 3, 1e-12);

  // The group the 12 pairings generate closes at 120 elements.
  std::vector<Mat4> group{Mat4::identity()};
  for (std::size_t i = 0; i < group.size() && group.size() <= 1000; ++i)
    for (const DomainFace& face : m.faces) {
      const Mat4 g = face.pairing * group[i];
      const bool known = std::any_of(group.begin(), group.end(),
                                     [&](const Mat4& h) { return max_difference(g, h) < 1e-9; });
      if (!known) group.push_back(g);
    }
  EXPECT_EQ(group.size(), 120u);
}

// Signed turn about n that carries chart point a to chart point b (azimuth difference).
double turn_about(const Vec3& n, const Vec3& a, const Vec3& b) {
  const Vec3 pa = a - dot(a, n) * n, pb = b - dot(b, n) * n;
  return std::atan2(dot(n, cross(pa, pb)), dot(pa, pb));
}

void expect_opposite_faces_turned(GeometryKind kind, const Manifold& m, double turn) {
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const DomainFace& face = m.faces[f];
    EXPECT_NEAR(length(m.faces[face.partner].normal + face.normal), 0, 1e-15);
    for (int i : m.domain.faces[f]) {
      const Vec3 v = m.domain.vertices[i];
      const Vec3 image = chart(kind, face.pairing * lift(kind, v));
      EXPECT_NEAR(dot(image, face.normal), -face.delta, 1e-12);  // on the opposite face
      EXPECT_NEAR(turn_about(face.normal, v, image), turn, 1e-12);
    }
  }
}

TEST(PoincareDodecahedralSpace, TurnsEachFaceOntoTheOppositeByATenth) {
  expect_opposite_faces_turned(kS3, make_poincare_dodecahedral_space(), -kPi / 5);
}

TEST(SeifertWeberSpace, TurnsEachFaceOntoTheOppositeByThreeTenths) {
  const Manifold m = make_seifert_weber_space();
  const double k = std::sqrt((8 * std::sqrt(5.0) - 15) / 5);
  EXPECT_NEAR(k, 0.76007, 5e-6);
  for (const DomainFace& face : m.faces) {
    EXPECT_NEAR(face.delta, k, 1e-15);
    EXPECT_NEAR(std::atanh(face.delta), 0.99638, 5e-6);
  }
  for (int e = 0; e < 30; ++e) EXPECT_NEAR(dihedral_angle(kH3, m, e), 2 * kPi / 5, 1e-12);
  expect_opposite_faces_turned(kH3, m, -3 * kPi / 5);
}

void expect_cycles(GeometryKind kind, const Manifold& m, std::size_t count, std::size_t steps,
                   double angle_sum, int order) {
  const auto cycles = edge_cycles(kind, m);
  EXPECT_EQ(cycles.size(), count);
  for (const EdgeCycle& c : cycles) {
    EXPECT_EQ(c.edges.size(), steps);
    EXPECT_NEAR(c.angle_sum, angle_sum, 1e-11);
    EXPECT_EQ(c.order, order);
    Mat4 h = Mat4::identity();
    for (int i = 0; i < order; ++i) h = c.transformation * h;
    EXPECT_LT(distance_from_identity(h), 1e-9);
  }
}

// T3: 3 classes of 4 edges at 90 deg. Mirrored: each edge is its own class, visited from both
// faces (angle sum pi, order 2: four copies of 90 deg around it). Poincare: 10 classes of 3 at
// 120 deg. Seifert-Weber: 6 classes of 5 at 72 deg.
TEST(EdgeCycles, CloseUpAroundEveryEdge) {
  expect_cycles(kE3, make_torus(kE3, 1), 3, 4, 2 * kPi, 1);
  expect_cycles(kH3, make_mirrored_dodecahedron(), 30, 2, kPi, 2);
  expect_cycles(kS3, make_poincare_dodecahedral_space(), 10, 3, 2 * kPi, 1);
  expect_cycles(kH3, make_seifert_weber_space(), 6, 5, 2 * kPi, 1);
}

// The Seifert-Weber dodecahedron with face f screwed by twists[f] about its normal.
Manifold twisted_seifert_weber(const std::vector<double>& twists) {
  std::vector<DomainFace> faces = make_seifert_weber_space().faces;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Vec3 n = faces[f].normal;
    faces[f].pairing = model::translation(kH3, -2 * std::atanh(faces[f].delta) * n) *
                       model::rotation(n, twists[f]);
  }
  return make_generic(kH3, faces);
}

TEST(EdgeCycles, CatchAWrongTwist) {
  const double t = 3 * kPi / 5;
  // The mirror image (the other sense on every face) is the same space, reflected.
  EXPECT_NO_THROW(validate_manifold(kH3, twisted_seifert_weber(std::vector<double>(12, t))));
  // A tenth turn maps faces onto faces but piles 3 x 72 deg around an edge.
  const std::string tenth = scene_error_of(
      [&] { validate_manifold(kH3, twisted_seifert_weber(std::vector<double>(12, -kPi / 5))); });
  EXPECT_NE(tenth.find("edge cycle"), std::string::npos) << tenth;
  EXPECT_NE(tenth.find("216.0"), std::string::npos) << tenth;
  // One pair turned the other way.
  std::vector<double> mixed(12, -t);
  mixed[0] = t, mixed[1] = t;
  const std::string one_pair =
      scene_error_of([&] { validate_manifold(kH3, twisted_seifert_weber(mixed)); });
  EXPECT_NE(one_pair.find("edge cycle"), std::string::npos) << one_pair;
}

// Largest face constraint N . X - delta at chart point x: positive outside the domain.
double outside(const Manifold& m, const Vec3& x, int* face = nullptr) {
  double worst = -INFINITY;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const double s = dot(m.faces[f].normal, x) - m.faces[f].delta;
    if (s <= worst) continue;
    worst = s;
    if (face) *face = static_cast<int>(f);
  }
  return worst;
}

// Follows the geodesic (p, v) through `crossings` faces as algorithm 1 does, checking that
// each continuation starts on the partner face and heads into the domain.
void follow(GeometryKind kind, const Manifold& m, Vec4 p, Vec4 v, int crossings) {
  for (int c = 0; c < crossings; ++c) {
    double t0 = 1e-6, t1 = t0;
    ASSERT_LT(outside(m, chart(kind, model::geodesic_point(kind, p, v, t0))), 0)
        << "crossing " << c;
    while (outside(m, chart(kind, model::geodesic_point(kind, p, v, t1))) < 0) {
      t0 = t1;
      t1 += 0.01;
      ASSERT_LT(t1, 20) << "the ray never leaves";
    }
    for (int i = 0; i < 60; ++i) {
      const double mid = (t0 + t1) / 2;
      (outside(m, chart(kind, model::geodesic_point(kind, p, v, mid))) < 0 ? t0 : t1) = mid;
    }
    const Vec4 q = model::geodesic_point(kind, p, v, t1),
               w = model::geodesic_tangent(kind, p, v, t1);
    int f = -1;
    outside(m, chart(kind, q), &f);
    const DomainFace& face = m.faces[f];
    p = model::normalize_point(kind, face.pairing * q);
    v = face.pairing * w;
    const DomainFace& partner = m.faces[face.partner];
    EXPECT_NEAR(dot(partner.normal, chart(kind, p)), partner.delta, 1e-9);
    EXPECT_LT(outside(m, chart(kind, p)), 1e-9);
    EXPECT_NEAR(model::inner(kind, v, v), 1, 1e-9);
    v = model::normalize_tangent(kind, p, v);  // as the renderer does after every isometry
  }
}

TEST(RayCrossing, LeavingRaysReenterTheDomain) {
  const std::vector<std::pair<GeometryKind, Manifold>> spaces = {
      {kE3, make_torus(kE3, 1)},
      {kH3, make_mirrored_dodecahedron()},
      {kS3, make_poincare_dodecahedral_space()},
      {kH3, make_seifert_weber_space()}};
  for (const auto& [kind, m] : spaces)
    for (int i = 0; i < 24; ++i) {
      // Fibonacci-sphere directions, turned off the symmetry planes (a ray into an edge
      // leaves through either face), from two starting points inside the domain.
      const double z = 1 - (2 * i + 1) / 24.0, phi = 0.5 + i * kPi * (3 - std::sqrt(5.0));
      const Vec3 d{std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z};
      const Mat4 start = model::translation(kind, i % 2 ? Vec3{0.1, -0.2, 0.15} : Vec3{});
      SCOPED_TRACE(m.name + " direction " + std::to_string(i));
      follow(kind, m, start * model::origin(), start * Vec4{d, 0}, 12);
    }
}

// The torus as a "generic" manifold document, for crafting bad variants.
nlohmann::ordered_json torus_document() {
  nlohmann::ordered_json faces = nlohmann::ordered_json::array();
  for (const DomainFace& f : make_torus(kE3, 1).faces) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const auto& row : f.pairing.m) rows.push_back({row[0], row[1], row[2], row[3]});
    faces.push_back({{"normal", {f.normal.x, f.normal.y, f.normal.z}},
                     {"distance", f.delta},
                     {"pairing", rows},
                     {"partner", f.partner}});
  }
  return {{"type", "generic"}, {"faces", faces}};
}

Manifold read(const nlohmann::ordered_json& doc, GeometryKind kind) {
  return read_manifold(JsonNode(doc, "manifold"), kind);
}
std::string read_error(const nlohmann::ordered_json& doc, GeometryKind kind = kE3) {
  return scene_error_of([&] { read(doc, kind); });
}

TEST(ManifoldLoader, ReadsEveryType) {
  using Json = nlohmann::ordered_json;
  EXPECT_TRUE(read(Json(nullptr), kH3).faces.empty());
  EXPECT_EQ(read(Json::parse(R"({"type": "none"})"), kS3).name, "none");
  const Manifold torus =
      read(Json::parse(R"({"type": "torus", "size": 4, "max_crossings": 5})"), kE3);
  EXPECT_EQ(torus.name, "torus");
  EXPECT_EQ(torus.faces[0].delta, 2);
  EXPECT_EQ(torus.max_crossings, 5);
  EXPECT_EQ(read(Json::parse(R"({"type": "mirrored-dodecahedron"})"), kH3).faces[3].partner, 3);
  EXPECT_EQ(read(Json::parse(R"({"type": "seifert-weber"})"), kH3).name, "seifert-weber");
  EXPECT_EQ(read(Json::parse(R"({"type": "poincare-dodecahedral"})"), kS3).max_crossings, 16);
  const Manifold generic = read(torus_document(), kE3);
  EXPECT_EQ(generic.name, "generic");
  EXPECT_EQ(generic.domain.edges.size(), 12u);
}

TEST(ManifoldLoader, NamesTheFieldOfEachMistake) {
  using Json = nlohmann::ordered_json;
  EXPECT_EQ(read_error(Json::parse(R"({"type": "poincare-dodecahedral"})"), kH3),
            "manifold.type: \"poincare-dodecahedral\" is a spherical manifold, but the scene's "
            "geometry is hyperbolic");
  EXPECT_EQ(read_error(Json::parse(R"({"type": "torus", "size": 2})"), kS3),
            "manifold.type: \"torus\" is a euclidean manifold, but the scene's geometry is "
            "spherical");
  EXPECT_EQ(read_error(Json::parse(R"({"type": "seifert-weber", "size": 2})"), kH3),
            "manifold: unknown field \"size\"");
  EXPECT_EQ(
      read_error(Json::parse(R"({"type": "klein-bottle"})"))
          .rfind("manifold.type: unknown manifold type \"klein-bottle\" (expected \"none\", ", 0),
      0u);
  EXPECT_EQ(read_error(Json::parse(R"({"type": "torus", "size": -1})")),
            "manifold.size: must be > 0");
  EXPECT_EQ(read_error(Json::parse(R"({"type": "none", "max_crossings": 65})")),
            "manifold.max_crossings: must be an integer in [0, 64]");
  EXPECT_EQ(read_error(Json::parse(R"([1, 2])")), "manifold: must be null or an object");

  auto doc = torus_document();
  doc["faces"][2]["pairing"][1] = {0, 1, 0};
  EXPECT_EQ(read_error(doc), "manifold.faces[2].pairing[1]: must be a row of 4 numbers");
  doc = torus_document();
  doc["faces"][2]["partner"] = 6;
  EXPECT_EQ(read_error(doc), "manifold.faces[2].partner: must be an integer in [0, 5]");
  doc = torus_document();
  doc["faces"][0]["colour"] = 1;
  EXPECT_EQ(read_error(doc), "manifold.faces[0]: unknown field \"colour\"");
}

TEST(ManifoldValidation, ReportsWhichFaceFailsAndByHowMuch) {
  auto doc = torus_document();
  doc["faces"][0]["pairing"][0][0] = 1.02;
  EXPECT_EQ(read_error(doc),
            "manifold.faces[0].pairing: not an isometry of euclidean space "
            "(error 4.0e-02 > 1e-06)");
  doc = torus_document();
  doc["faces"][0]["pairing"][0][3] = -1.5;
  EXPECT_EQ(read_error(doc),
            "manifold.faces[0].pairing: does not map face 0 onto face 1 (vertex off by 5.0e-01)");
  doc = torus_document();
  doc["faces"][2]["partner"] = 1;
  EXPECT_EQ(read_error(doc),
            "manifold.faces[2].partner: face 1's partner is 0, not 2 "
            "(pairings must be mutual)");
  doc = torus_document();
  // Face 1 goes onto face 0 with a quarter turn about x: not the way g_0 came.
  doc["faces"][1]["pairing"] = {{1, 0, 0, 2}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
  EXPECT_EQ(read_error(doc), "manifold.faces[0]: g_1 . g_0 is not the identity (error 1.0e+00)");
  doc = torus_document();
  doc["faces"].erase(5);
  doc["faces"].erase(4);
  EXPECT_EQ(read_error(doc), "manifold: the domain is unbounded (some direction crosses no face)");
  doc = torus_document();
  doc["faces"][0]["normal"] = {2, 0, 0};
  EXPECT_EQ(read_error(doc), "manifold.faces[0].normal: must be a unit vector (length 2.000000)");
  // Faces paired with themselves: the identity sends rays back out, a quarter turn is no mirror.
  doc = torus_document();
  doc["faces"][0]["partner"] = 0;
  doc["faces"][0]["pairing"] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  EXPECT_EQ(read_error(doc),
            "manifold.faces[0].pairing: a ray leaving through face 0 leaves "
            "again through face 0 instead of entering the domain");
  doc["faces"][0]["pairing"] = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
  EXPECT_EQ(read_error(doc).rfind("manifold.faces[0].pairing: a face paired with itself needs "
                                  "the reflection in its plane (g . g - I: 2.0e+00",
                                  0),
            0u);
  doc["faces"][0]["pairing"] = {{-1, 0, 0, 2}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  doc["faces"][1]["partner"] = 1;
  doc["faces"][1]["pairing"] = {{-1, 0, 0, -2}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  EXPECT_NO_THROW(read(doc, kE3));  // x mirrors, y and z translations: a valid orbifold
}

// The quarter-turn space: the torus with the x faces glued by a screw. Not a translation, but
// its edge cycles still close (3 x 4 right angles), so it validates.
TEST(ManifoldValidation, AcceptsTheQuarterTurnSpace) {
  std::vector<DomainFace> faces = make_torus(kE3, 1).faces;
  faces[0].pairing = faces[0].pairing * model::rotation({1, 0, 0}, kPi / 2);
  faces[1].pairing = model::inverse_isometry(kE3, faces[0].pairing);
  const Manifold m = make_generic(kE3, faces);
  EXPECT_NO_THROW(validate_manifold(kE3, m));
  expect_cycles(kE3, m, 3, 4, 2 * kPi, 1);
}

// Ideal vertices (cusps) are allowed; vertices beyond the sphere at infinity are not.
TEST(ManifoldValidation, HyperbolicDomainsMustHaveFiniteVolume) {
  std::vector<DomainFace> faces = make_mirrored_dodecahedron().faces;
  for (DomainFace& f : faces) f.delta = 0.8;  // vertices beyond the Klein ball
  EXPECT_EQ(scene_error_of([&] { validate_manifold(kH3, make_generic(kH3, faces)); })
                .rfind("manifold: the domain reaches beyond the sphere at infinity (vertex 0 at "
                       "Klein radius 1.0",
                       0),
            0u);
}

}  // namespace
}  // namespace geodesic
