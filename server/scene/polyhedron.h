// A convex polyhedron given by face planes in a chart (Klein in H3, gnomonic in S3, plain
// coordinates in E3): {X : normal_f . X <= delta_f for every face f}. Charts map geodesic
// planes to flat planes, so the fundamental domain of a manifold is an ordinary convex
// polyhedron there, and its vertices, edges and faces follow from linear algebra alone.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/model.h"
#include "geometry/vec.h"

namespace geodesic {

struct EdgeTube;  // scene/scene.h, which includes this header

struct ChartPlane {
  Vec3 normal;  // outward unit normal
  double delta = 0;
};

struct Polyhedron {
  // False when the half-spaces leave a direction unconstrained (fewer than 4 faces, or some
  // d != 0 with normal_f . d <= 0 for every f); everything else is then empty.
  bool bounded = false;
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 2>> edges;       // vertex index pairs, first < second
  std::vector<std::vector<int>> faces;         // per plane: its vertices, counter-clockwise
                                               // seen from outside (fewer than 3: the plane
                                               // does not bound a face)
  std::vector<std::vector<int>> vertex_faces;  // per vertex: the planes through it
};

// A vertex of an H3 polyhedron at Klein radius 1 (to this tolerance) is ideal: a point of the
// sphere at infinity, the tip of a cusp of finite volume. Finite vertices that close are
// farther than distance 8 from the chart's centre, beyond any domain the loader builds.
inline constexpr double kIdealTolerance = 1e-7;
inline bool ideal_vertex(GeometryKind kind, const Vec3& v) {
  return kind == GeometryKind::Hyperbolic && std::abs(length(v) - 1) <= kIdealTolerance;
}

// Bounded with no vertices means the half-spaces have no common point. `tolerance` (relative
// to the largest |delta|) decides which planes pass through a vertex.
Polyhedron make_polyhedron(const std::vector<ChartPlane>& planes, double tolerance = 1e-9);

// The faces (plane indices) containing both ends of edge e.
std::vector<int> edge_faces(const Polyhedron& p, int e);

// The tube of chart radius `radius` along every edge (scene.h EdgeTube). Throws SceneError (a
// reason without a path) when a tube leaves the Klein ball in H3.
std::vector<EdgeTube> make_edge_tubes(GeometryKind kind, const Polyhedron& p, double radius,
                                      uint32_t material);

}  // namespace geodesic
