#include "scene/polyhedron.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "scene/scene.h"

namespace geodesic {
namespace {

bool parallel(const Vec3& a, const Vec3& b) { return length(cross(a, b)) < 1e-9; }

// Some unit vector perpendicular to unit n.
Vec3 perpendicular(const Vec3& n) {
  const Vec3 helper = std::abs(n.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  return normalize(cross(n, helper));
}

// A d != 0 with normal . d <= 0 for every plane makes the set unbounded. If one exists, the
// cone of such d has an extreme ray on two independent planes, i.e. along +-(Na x Nb) — or
// every normal is parallel and any perpendicular d works.
bool bounded(const std::vector<ChartPlane>& planes) {
  if (planes.size() < 4) return false;
  bool independent_pair = false;
  for (std::size_t a = 0; a < planes.size(); ++a)
    for (std::size_t b = a + 1; b < planes.size(); ++b) {
      if (parallel(planes[a].normal, planes[b].normal)) continue;
      independent_pair = true;
      const Vec3 axis = normalize(cross(planes[a].normal, planes[b].normal));
      for (const Vec3& d : {axis, -axis}) {
        const bool escapes = std::all_of(planes.begin(), planes.end(), [&](const ChartPlane& p) {
          return dot(p.normal, d) <= 1e-12;
        });
        if (escapes) return false;
      }
    }
  return independent_pair;
}

}  // namespace

Polyhedron make_polyhedron(const std::vector<ChartPlane>& planes, double tolerance) {
  Polyhedron p;
  p.faces.resize(planes.size());
  if (!bounded(planes)) return p;
  p.bounded = true;

  double scale = 1;
  for (const ChartPlane& plane : planes) scale = std::max(scale, std::abs(plane.delta));
  const double tol = tolerance * scale;
  const int n = static_cast<int>(planes.size());
  auto inside = [&](const Vec3& x) {
    return std::all_of(planes.begin(), planes.end(),
                       [&](const ChartPlane& pl) { return dot(pl.normal, x) <= pl.delta + tol; });
  };

  // Vertices: feasible intersections of plane triples (Cramer's rule), deduplicated.
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      for (int c = b + 1; c < n; ++c) {
        const Vec3 &na = planes[a].normal, &nb = planes[b].normal, &nc = planes[c].normal;
        const double det = dot(na, cross(nb, nc));
        if (std::abs(det) < 1e-9) continue;
        const Vec3 x = (planes[a].delta * cross(nb, nc) + planes[b].delta * cross(nc, na) +
                        planes[c].delta * cross(na, nb)) /
                       det;
        if (!inside(x)) continue;
        const bool known = std::any_of(p.vertices.begin(), p.vertices.end(),
                                       [&](const Vec3& v) { return length(v - x) < 10 * tol; });
        if (!known) p.vertices.push_back(x);
      }

  for (const Vec3& v : p.vertices) {
    std::vector<int> on;
    for (int f = 0; f < n; ++f)
      if (std::abs(dot(planes[f].normal, v) - planes[f].delta) < 10 * tol) on.push_back(f);
    p.vertex_faces.push_back(on);
  }

  // Edges: vertex pairs on two non-parallel common planes.
  const int nv = static_cast<int>(p.vertices.size());
  for (int i = 0; i < nv; ++i)
    for (int j = i + 1; j < nv; ++j) {
      std::vector<int> common;
      std::set_intersection(p.vertex_faces[i].begin(), p.vertex_faces[i].end(),
                            p.vertex_faces[j].begin(), p.vertex_faces[j].end(),
                            std::back_inserter(common));
      bool edge = false;
      for (std::size_t s = 0; s < common.size() && !edge; ++s)
        for (std::size_t t = s + 1; t < common.size() && !edge; ++t)
          edge = !parallel(planes[common[s]].normal, planes[common[t]].normal);
      if (edge) p.edges.push_back({i, j});
    }

  // Face polygons: sorted by angle about the outward normal (counter-clockwise from outside).
  for (int i = 0; i < nv; ++i)
    for (int f : p.vertex_faces[i]) p.faces[f].push_back(i);
  for (int f = 0; f < n; ++f) {
    auto& poly = p.faces[f];
    if (poly.empty()) continue;
    Vec3 centre;
    for (int i : poly) centre += p.vertices[i];
    centre = centre / static_cast<double>(poly.size());
    const Vec3 u = perpendicular(planes[f].normal), w = cross(planes[f].normal, u);
    auto angle = [&](int i) {
      const Vec3 r = p.vertices[i] - centre;
      return std::atan2(dot(r, w), dot(r, u));
    };
    std::sort(poly.begin(), poly.end(), [&](int a, int b) { return angle(a) < angle(b); });
  }
  return p;
}

std::vector<int> edge_faces(const Polyhedron& p, int e) {
  const auto& a = p.vertex_faces[p.edges[e][0]];
  const auto& b = p.vertex_faces[p.edges[e][1]];
  std::vector<int> common;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
  return common;
}

std::vector<EdgeTube> make_edge_tubes(GeometryKind kind, const Polyhedron& p, double radius,
                                      uint32_t material) {
  std::vector<EdgeTube> tubes;
  for (const auto& [ia, ib] : p.edges) {
    const Vec3 a = p.vertices[ia], b = p.vertices[ib];
    // The Klein chart is the open unit ball: a tube poking out of it has no model points (the
    // capsule is convex, so its ends' balls tell).
    if (kind == GeometryKind::Hyperbolic && std::max(length(a), length(b)) + radius >= 1)
      throw SceneError("tubes of chart radius " + std::to_string(radius) +
                       " leave the hyperbolic chart (|X| >= 1)");
    tubes.push_back({a, b, radius, material});
  }
  return tubes;
}

}  // namespace geodesic
