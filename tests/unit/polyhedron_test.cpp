// Convex polyhedra from face planes: vertex, edge and face counts of known solids (including
// vertices where four planes meet), face orientation, unbounded and empty inputs, and the edge
// tubes drawn along a domain's edges.
#include "scene/polyhedron.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "scene/manifold.h"
#include "scene/scene.h"

namespace geodesic {
namespace {

std::vector<ChartPlane> cube(double h) {
  return {{{1, 0, 0}, h},  {{-1, 0, 0}, h}, {{0, 1, 0}, h},
          {{0, -1, 0}, h}, {{0, 0, 1}, h},  {{0, 0, -1}, h}};
}

// Every polygon runs counter-clockwise seen from outside: consecutive corners turn about +N.
void expect_outward_counter_clockwise(const Polyhedron& p, const std::vector<ChartPlane>& planes) {
  for (std::size_t f = 0; f < planes.size(); ++f) {
    const auto& poly = p.faces[f];
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec3 a = p.vertices[poly[i]], b = p.vertices[poly[(i + 1) % poly.size()]],
                 c = p.vertices[poly[(i + 2) % poly.size()]];
      EXPECT_GT(dot(cross(b - a, c - b), planes[f].normal), 1e-12) << "face " << f;
      EXPECT_NEAR(dot(planes[f].normal, a), planes[f].delta, 1e-12);
    }
  }
}

TEST(Polyhedron, CubeHasEightVerticesTwelveEdgesSixSquares) {
  const auto planes = cube(0.5);
  const Polyhedron p = make_polyhedron(planes);
  ASSERT_TRUE(p.bounded);
  EXPECT_EQ(p.vertices.size(), 8u);
  EXPECT_EQ(p.edges.size(), 12u);
  ASSERT_EQ(p.faces.size(), 6u);
  for (const auto& face : p.faces) EXPECT_EQ(face.size(), 4u);
  for (const Vec3& v : p.vertices) EXPECT_NEAR(length(v), 0.5 * std::sqrt(3.0), 1e-15);
  for (int e = 0; e < 12; ++e) {
    const auto& [a, b] = p.edges[e];
    EXPECT_LT(a, b);
    EXPECT_NEAR(length(p.vertices[a] - p.vertices[b]), 1.0, 1e-15);
    EXPECT_EQ(edge_faces(p, e).size(), 2u);
  }
  expect_outward_counter_clockwise(p, planes);
}

TEST(Polyhedron, DodecahedronHasTwentyVerticesThirtyEdgesTwelvePentagons) {
  std::vector<ChartPlane> planes;
  for (const Vec3& n : dodecahedron_normals()) planes.push_back({n, 1});
  const Polyhedron p = make_polyhedron(planes);
  ASSERT_TRUE(p.bounded);
  EXPECT_EQ(p.vertices.size(), 20u);
  EXPECT_EQ(p.edges.size(), 30u);
  for (const auto& face : p.faces) EXPECT_EQ(face.size(), 5u);
  for (const auto& on : p.vertex_faces) EXPECT_EQ(on.size(), 3u);
  for (int e = 0; e < 30; ++e) EXPECT_EQ(edge_faces(p, e).size(), 2u);
  expect_outward_counter_clockwise(p, planes);
}

// Four planes through each vertex: the triples give each vertex four times over.
TEST(Polyhedron, OctahedronMergesVerticesOfFourPlanes) {
  std::vector<ChartPlane> planes;
  for (double x : {-1.0, 1.0})
    for (double y : {-1.0, 1.0})
      for (double z : {-1.0, 1.0}) planes.push_back({normalize(Vec3{x, y, z}), 1 / std::sqrt(3.0)});
  const Polyhedron p = make_polyhedron(planes);
  ASSERT_TRUE(p.bounded);
  EXPECT_EQ(p.vertices.size(), 6u);
  EXPECT_EQ(p.edges.size(), 12u);
  for (const auto& face : p.faces) EXPECT_EQ(face.size(), 3u);
  for (const auto& on : p.vertex_faces) EXPECT_EQ(on.size(), 4u);
  expect_outward_counter_clockwise(p, planes);
}

TEST(Polyhedron, OpenSidesAreUnbounded) {
  auto open_box = cube(1);
  open_box.pop_back();  // no -z face: the box is open downwards
  EXPECT_FALSE(make_polyhedron(open_box).bounded);
  EXPECT_TRUE(make_polyhedron(open_box).vertices.empty());

  auto slab_pairs = cube(1);
  slab_pairs.resize(4);  // x and y slabs only: a square prism infinite along z
  EXPECT_FALSE(make_polyhedron(slab_pairs).bounded);

  EXPECT_FALSE(make_polyhedron({{{1, 0, 0}, 1}, {{0, 1, 0}, 1}, {{0, 0, 1}, 1}}).bounded);
  // Four planes but all normals in the upper half-space: (0, 0, -1) is free.
  EXPECT_FALSE(make_polyhedron({{normalize(Vec3{1, 0, 1}), 1},
                                {normalize(Vec3{-1, 0, 1}), 1},
                                {normalize(Vec3{0, 1, 1}), 1},
                                {normalize(Vec3{0, -1, 1}), 1}})
                   .bounded);
}

TEST(Polyhedron, DisjointHalfSpacesAreEmpty) {
  auto planes = cube(1);
  planes[1].delta = -2;  // x >= 2 and x <= 1
  const Polyhedron p = make_polyhedron(planes);
  EXPECT_TRUE(p.bounded);
  EXPECT_TRUE(p.vertices.empty());
}

TEST(Polyhedron, RedundantPlaneBoundsNoFace) {
  auto planes = cube(1);
  planes.push_back({{1, 0, 0}, 5});
  planes.push_back({normalize(Vec3{1, 1, 0}), std::sqrt(2.0)});  // touches one edge only
  const Polyhedron p = make_polyhedron(planes);
  EXPECT_EQ(p.vertices.size(), 8u);
  EXPECT_EQ(p.edges.size(), 12u);
  EXPECT_TRUE(p.faces[6].empty());
  EXPECT_EQ(p.faces[7].size(), 2u);
}

// Distance from x to the segment [a, b].
double segment_distance(const Vec3& x, const Vec3& a, const Vec3& b) {
  const double t = std::clamp(dot(x - a, b - a) / dot(b - a, b - a), 0.0, 1.0);
  return length(x - (a + t * (b - a)));
}

// Rings of six vertices along each edge, sections at most two diameters long (a tight
// bounding box for each triangle): the first vertex of each edge's rings.
std::vector<std::size_t> ring_starts(const Polyhedron& p, double radius) {
  std::vector<std::size_t> starts{0};
  for (const auto& [ia, ib] : p.edges) {
    const double sections = std::ceil(length(p.vertices[ib] - p.vertices[ia]) / (4 * radius));
    starts.push_back(starts.back() + 6 * (std::size_t(sections) + 1));
  }
  return starts;
}

TEST(EdgeTubes, SixSidedCappedPrismPerEdge) {
  const Polyhedron p = make_polyhedron(cube(1));
  const TriangleMesh mesh = make_edge_tubes(GeometryKind::Euclidean, p, 0.05, 3);
  EXPECT_EQ(mesh.material, 3u);
  const std::vector<std::size_t> starts = ring_starts(p, 0.05);
  // The cube's edges are 2 long: ten sections of 0.2, eleven rings.
  EXPECT_EQ(starts[1], 66u);
  EXPECT_EQ(mesh.positions.size(), starts.back());
  EXPECT_EQ(mesh.indices.size(), 12u * (10 * 12 + 8) * 3);
  EXPECT_TRUE(mesh.normals.empty());
  // Every vertex sits at the radius from its own edge (E3: exponential = chart coordinates).
  for (std::size_t e = 0; e < p.edges.size(); ++e)
    for (std::size_t k = starts[e]; k < starts[e + 1]; ++k) {
      const Vec3 x = mesh.positions[k];
      EXPECT_NEAR(segment_distance(x, p.vertices[p.edges[e][0]], p.vertices[p.edges[e][1]]), 0.05,
                  1e-12);
    }
  // Closed surface, consistently wound: every directed edge appears once, reversed once.
  std::multiset<std::pair<uint32_t, uint32_t>> half_edges;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
    for (int i = 0; i < 3; ++i)
      half_edges.insert({mesh.indices[t + i], mesh.indices[t + (i + 1) % 3]});
  for (const auto& [a, b] : half_edges) {
    EXPECT_EQ(half_edges.count({a, b}), 1u);
    EXPECT_EQ(half_edges.count({b, a}), 1u);
  }
  // Outward winding: each side triangle's normal points away from its edge's axis.
  const Vec3 a = p.vertices[p.edges[0][0]], b = p.vertices[p.edges[0][1]];
  const Vec3 t0 = mesh.positions[mesh.indices[0]], t1 = mesh.positions[mesh.indices[1]],
             t2 = mesh.positions[mesh.indices[2]];
  const Vec3 centre = (t0 + t1 + t2) / 3.0;
  const Vec3 axis_point = a + dot(centre - a, normalize(b - a)) * normalize(b - a);
  EXPECT_GT(dot(cross(t1 - t0, t2 - t0), centre - axis_point), 0);
}

TEST(EdgeTubes, HyperbolicTubesFollowTheChartEdges) {
  const Manifold m = make_mirrored_dodecahedron();
  constexpr auto kind = GeometryKind::Hyperbolic;
  const TriangleMesh mesh = make_edge_tubes(kind, m.domain, 0.02, 0);
  const std::vector<std::size_t> starts = ring_starts(m.domain, 0.02);
  ASSERT_EQ(starts.size(), 31u);
  ASSERT_EQ(mesh.positions.size(), starts.back());
  for (std::size_t e = 0; e < 30; ++e)
    for (std::size_t k = starts[e]; k < starts[e + 1]; ++k) {
      const Vec3 x = model::chart(kind, model::exp_origin(kind, mesh.positions[k]));
      const auto& [ia, ib] = m.domain.edges[e];
      EXPECT_NEAR(segment_distance(x, m.domain.vertices[ia], m.domain.vertices[ib]), 0.02, 1e-9);
    }
  // Seifert-Weber's vertices are at Klein radius 0.956: a fat tube pokes out of the ball.
  EXPECT_THROW(make_edge_tubes(kind, make_seifert_weber_space().domain, 0.3, 0), SceneError);
}

}  // namespace
}  // namespace geodesic
