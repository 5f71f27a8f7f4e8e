// The face-crossing twin of the shader, against an independent oracle (bisection on the domain
// constraints) and over long runs: rays through faces, edges and vertices, and 10^3 crossings.
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>

#include "twins/cell_tracer.h"
#include "scene/catalogue.h"
#include "scene/dirichlet_domain.h"

namespace geodesic {
namespace {

Scene scene_of(GeometryKind kind, Manifold manifold) {
  Scene scene;
  scene.geometry = kind;
  scene.manifold = std::move(manifold);
  return scene;
}

// Largest face constraint N . X - delta of a model point in the cell (positive outside).
double outside(GeometryKind k, const Cell& cell, const Vec4& q) {
  const Vec3 x = model::chart(k, cell.chart_isometry * q);
  double worst = -INFINITY;
  for (const CellFace& f : cell.faces) worst = std::max(worst, dot(f.normal, x) - f.delta);
  return worst;
}

// Deviation of a point and tangent from the model: |<p,p> -+ 1| and |<p,v>| (E3: |p.w - 1| and
// |v.w|), and |<v,v> - 1|.
double off_model(GeometryKind k, const CellRay& r) {
  const double v_unit = std::abs(model::inner(k, r.v, r.v) - 1);
  if (k == GeometryKind::Euclidean) return std::max({std::abs(r.p.w - 1), std::abs(r.v.w), v_unit});
  const double on_model = model::inner(k, r.p, r.p) - model::inner(k, model::origin(), model::origin());
  return std::max({std::abs(on_model), std::abs(model::inner(k, r.p, r.v)), v_unit});
}

bool same(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// b = -a as float reads them.
bool opposite_in_float(const Vec3& a, const Vec3& b) {
  return float(b.x) == -float(a.x) && float(b.y) == -float(a.y) && float(b.z) == -float(a.z);
}

struct Space {
  GeometryKind kind;
  Manifold manifold;
};

std::vector<Space> spaces() {
  return {{GeometryKind::Euclidean, make_torus(GeometryKind::Euclidean, 1)},
          {GeometryKind::Hyperbolic, make_mirrored_dodecahedron()},
          {GeometryKind::Spherical, make_poincare_dodecahedral_space()},
          {GeometryKind::Hyperbolic, make_seifert_weber_space()}};
}

TEST(CellTracer, ExitDistanceMatchesBisectionOnTheDomain) {
  for (const Space& space : spaces()) {
    const auto cells = build_cells(scene_of(space.kind, space.manifold));
    for (int i = 0; i < 32; ++i) {
      const double z = 1 - (2 * i + 1) / 32.0, phi = i * 2.39996;
      const Vec3 d{std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z};
      CellRay ray{model::origin(), {d, 0}, 0, -1};
      const CellExit exit = exit_cell(space.kind, cells, ray);
      double t0 = 0, t1 = 10;
      for (int k = 0; k < 80; ++k) {
        const double mid = (t0 + t1) / 2;
        (outside(space.kind, cells[0], model::geodesic_point(space.kind, ray.p, ray.v, mid)) < 0 ? t0 : t1) = mid;
      }
      EXPECT_NEAR(exit.t, t1, 1e-9) << space.manifold.name << " direction " << i;
    }
  }
}

// Straight at a vertex, at an edge's midpoint and at a face's centre: every crossing lands on
// the domain's boundary, the ray keeps going, nothing is NaN.
TEST(CellTracer, RaysThroughVerticesAndEdgesKeepGoing) {
  for (const Space& space : spaces()) {
    const auto cells = build_cells(scene_of(space.kind, space.manifold));
    const Polyhedron& domain = space.manifold.domain;
    const auto& e = domain.edges.at(0);
    const Vec3 targets[] = {domain.vertices.at(0),
                            (domain.vertices[e[0]] + domain.vertices[e[1]]) / 2,
                            space.manifold.faces[0].normal * space.manifold.faces[0].delta};
    for (const Vec3& target : targets) {
      CellRay ray{model::origin(), {normalize(target), 0}, 0, -1};
      double travelled = 0;
      for (int c = 0; c < 40; ++c) {
        const CellExit exit = exit_cell(space.kind, cells, ray);
        ASSERT_GE(exit.face, 0) << space.manifold.name;
        ASSERT_TRUE(std::isfinite(exit.t) && exit.t >= 0) << space.manifold.name;
        travelled += exit.t;
        ray = cross_face(space.kind, cells, ray, exit.face, exit.t);
        ASSERT_LT(outside(space.kind, cells[0], ray.p), 1e-9) << space.manifold.name;
      }
      EXPECT_GT(travelled, 1.0) << space.manifold.name;  // zero-length crossings at seams only
    }
  }
}

// 10^3 crossings in double: the ray stays on the model and inside the domain.
TEST(CellTracer, ThousandCrossingsStayOnTheModel) {
  for (const Space& space : spaces()) {
    const auto cells = build_cells(scene_of(space.kind, space.manifold));
    CellRay ray{model::origin(), {normalize(Vec3(0.3, 0.5, 0.81)), 0}, 0, -1};
    double worst = 0;
    for (int c = 0; c < 1000; ++c) {
      const CellExit exit = exit_cell(space.kind, cells, ray);
      ray = cross_face(space.kind, cells, ray, exit.face, exit.t);
      worst = std::max(worst, off_model(space.kind, ray));
      ASSERT_LT(outside(space.kind, cells[0], ray.p), 1e-9) << space.manifold.name << " " << c;
    }
    std::printf("%-26s worst deviation from the model after 1000 crossings: %.1e\n",
                space.manifold.name.c_str(), worst);
    EXPECT_LT(worst, 1e-12) << space.manifold.name;
  }
}

// The S3 atlas: going once around a great circle crosses cube faces and comes back home.
TEST(CellTracer, SphericalAtlasGoesAllTheWayAround) {
  const auto cells = build_cells(scene_of(GeometryKind::Spherical, {}));
  ASSERT_EQ(cells.size(), 8u);
  // The origin's cell is the one charted about e_w.
  int home_cell = 0;
  for (size_t c = 0; c < cells.size(); ++c)
    if ((cells[c].chart_isometry * model::origin()).w > 0.5) home_cell = int(c);
  CellRay ray{model::origin(), {normalize(Vec3(0.2, -0.4, -0.89)), 0}, home_cell, -1};
  const CellRay start = ray;
  double travelled = 0;
  int crossings = 0;
  while (travelled + 1e-12 < 2 * M_PI && crossings < 64) {
    const CellExit exit = exit_cell(GeometryKind::Spherical, cells, ray);
    ASSERT_GE(exit.face, 0);
    if (travelled + exit.t >= 2 * M_PI) break;
    travelled += exit.t;
    ray = cross_face(GeometryKind::Spherical, cells, ray, exit.face, exit.t);
    ++crossings;
  }
  const Vec4 home = model::geodesic_point(GeometryKind::Spherical, ray.p, ray.v, 2 * M_PI - travelled);
  EXPECT_NEAR(model::geodesic_distance(GeometryKind::Spherical, home, start.p), 0, 1e-12);
  EXPECT_EQ(ray.cell, start.cell);
  EXPECT_GE(crossings, 4);
}

// A lune's pieces all meet along one arc: a camera anywhere in the lune, on that arc or off it,
// is placed in a piece that holds it (the walls between pieces are not crossings to be paid).
// A domain whose faces come in opposite pairs (N . X = w, -N . X = w) but are listed apart, as
// the Dirichlet domains of the Hantzsche-Wendt space and the binary octahedral space are, is
// listed a pair at a time (the exit search's OPPOSITE_FACES), each face still entered from the
// face its domain pairs it with, carried by the same isometry.
TEST(CellTracer, OppositeFacesAreListedTogetherAndKeepTheirPartners) {
  for (const char* name : {"hantzsche-wendt", "binary-octahedral", "3-torus"}) {
    const CatalogueEntry* entry = find_catalogue_entry(name);
    ASSERT_NE(entry, nullptr) << name;
    const Manifold domain = dirichlet_domain(entry->kind, entry->generators).manifold;
    const auto faces_of = [&](const Vec3& normal, double delta) {  // the domain's face there
      for (size_t i = 0; i < domain.faces.size(); ++i)
        if (same(domain.faces[i].normal, normal) && domain.faces[i].delta == delta) return int(i);
      return -1;
    };
    bool apart = false;
    for (size_t i = 0; i + 1 < domain.faces.size(); i += 2)
      apart |= !opposite_in_float(domain.faces[i].normal, domain.faces[i + 1].normal);
    EXPECT_TRUE(apart) << name << ": the case needs faces listed apart";
    const auto cells = build_cells(scene_of(entry->kind, domain));
    ASSERT_EQ(cells.size(), 1u);
    const std::vector<CellFace>& faces = cells[0].faces;
    ASSERT_EQ(faces.size(), domain.faces.size()) << name;
    for (size_t k = 0; k < faces.size(); ++k) {
      if (k % 2 == 1) {
        EXPECT_TRUE(opposite_in_float(faces[k - 1].normal, faces[k].normal)) << name << " " << k;
        EXPECT_EQ(float(faces[k].delta), float(faces[k - 1].delta)) << name << " face " << k;
      }
      const int was = faces_of(faces[k].normal, faces[k].delta);
      ASSERT_GE(was, 0) << name << " face " << k;
      const CellFace& partner = faces.at(size_t(faces[k].partner));
      EXPECT_EQ(partner.partner, int(k)) << name << " face " << k;
      const DomainFace& expected = domain.faces[size_t(domain.faces[size_t(was)].partner)];
      EXPECT_TRUE(same(partner.normal, expected.normal)) << name << " face " << k;
      EXPECT_EQ(partner.delta, expected.delta) << name << " face " << k;
      EXPECT_EQ(std::memcmp(&faces[k].pairing, &domain.faces[size_t(was)].pairing, sizeof(Mat4)), 0)
          << name << " face " << k;
    }
  }
}

TEST(CellTracer, CameraGoesToThePieceThatHoldsIt) {
  constexpr auto kS3 = GeometryKind::Spherical;
  const auto cells = build_cells(scene_of(kS3, dirichlet_domain(kS3, lens_space_generators(3, 1)).manifold));
  ASSERT_EQ(cells.size(), 12u);  // 6 angles around the edge, and the arc cut in two
  int placed = 0;
  for (int i = 0; i < 200; ++i) {
    // Points spread over the lune (inradius pi / 3 about the origin), some near its edge.
    const double a = 0.7 * i, b = 1.3 * i + 0.2;
    const Vec3 w = Vec3{std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)} *
                   (1.0 * (i % 7 + 1) / 7.0);
    const Mat4 pose = model::translation(kS3, w);
    const CameraPlacement camera = place_camera(kS3, cells, pose);
    const Vec4 p = camera.pose * model::origin();
    EXPECT_LT(outside(kS3, cells[camera.cell], p), 1e-9) << i;
    placed += outside(kS3, cells[camera.cell], p) < 1e-9;
  }
  EXPECT_EQ(placed, 200);
}

}  // namespace
}  // namespace geodesic
