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

TEST(EdgeTubes, OneCapsulePerEdgeAlongIt) {
  const Polyhedron p = make_polyhedron(cube(1));
  const std::vector<EdgeTube> tubes = make_edge_tubes(GeometryKind::Euclidean, p, 0.05, 3);
  ASSERT_EQ(tubes.size(), 12u);
  for (std::size_t e = 0; e < tubes.size(); ++e) {
    EXPECT_EQ(tubes[e].material, 3u);
    EXPECT_EQ(tubes[e].radius, 0.05);
    EXPECT_EQ(length(tubes[e].a - p.vertices[p.edges[e][0]]), 0);
    EXPECT_EQ(length(tubes[e].b - p.vertices[p.edges[e][1]]), 0);
    EXPECT_EQ(length(tubes[e].b - tubes[e].a), 2);  // the cube's edges
  }
}

TEST(EdgeTubes, HyperbolicTubesStayInsideTheKleinBall) {
  constexpr auto kind = GeometryKind::Hyperbolic;
  const Manifold m = make_mirrored_dodecahedron();
  const auto tubes = make_edge_tubes(kind, m.domain, 0.02, 0);
  ASSERT_EQ(tubes.size(), 30u);
  for (const EdgeTube& t : tubes) EXPECT_LT(std::max(length(t.a), length(t.b)) + 0.02, 1);
  // Seifert-Weber's vertices are at Klein radius 0.956: a fat tube pokes out of the ball.
  const Polyhedron sw = make_seifert_weber_space().domain;
  EXPECT_NO_THROW(make_edge_tubes(kind, sw, 0.04, 0));
  EXPECT_THROW(make_edge_tubes(kind, sw, 0.05, 0), SceneError);
}

}  // namespace
}  // namespace geodesic
