#include "scene/plane_clipping.h"

#include <algorithm>
#include <cmath>

#include "scene/preparation_budget.h"

namespace geodesic {
namespace {

// The polyhedron of `kept`, with the planes that bound no face removed; open (see the
// header) when it reaches the horizon.
ClippedPolyhedron rebuild(const std::vector<ChartPlane>& candidates, std::vector<int> kept,
                          double tolerance, double horizon) {
  for (;;) {
    std::vector<ChartPlane> planes;
    for (int i : kept) planes.push_back(candidates[i]);
    ClippedPolyhedron c{make_polyhedron(planes, tolerance), {}};
    if (!c.polyhedron.bounded || c.polyhedron.vertices.empty()) {
      c.kept = std::move(kept);
      return c;
    }
    for (std::size_t i = 0; i < kept.size(); ++i)
      if (c.polyhedron.faces[i].size() >= 3) c.kept.push_back(kept[i]);
    if (c.kept.size() == kept.size()) {
      for (const Vec3& v : c.polyhedron.vertices)
        if (dot(v, v) >= horizon * horizon) c.polyhedron.bounded = false;
      return c;
    }
    kept = std::move(c.kept);
  }
}

double reach(const Polyhedron& p) {
  double r = 0;
  for (const Vec3& v : p.vertices) r = std::max(r, length(v));
  return r;
}

}  // namespace

ClippedPolyhedron clip_planes(const std::vector<ChartPlane>& candidates, double tolerance,
                              double horizon, std::size_t max_kept) {
  ClippedPolyhedron c;
  int clips = 0;
  for (int i = 0; i < static_cast<int>(candidates.size()); ++i) {
    const ChartPlane& plane = candidates[i];
    const bool open = !c.polyhedron.bounded;
    if (!open && plane.delta > reach(c.polyhedron) * (1 + 1e-9)) break;  // beyond every vertex
    bool cuts = open;
    for (const Vec3& v : c.polyhedron.vertices)
      cuts = cuts || dot(plane.normal, v) > plane.delta + tolerance * std::max(1.0, std::abs(plane.delta));
    if (!cuts) continue;
    if (c.kept.size() >= max_kept || ++clips > kMaxClips) {
      c.polyhedron.bounded = false;
      break;
    }
    check_preparation_budget();
    std::vector<int> next = c.kept;
    next.push_back(i);
    c = rebuild(candidates, std::move(next), tolerance, horizon);
    if (c.polyhedron.bounded && c.polyhedron.vertices.empty()) break;  // empty: nothing left
  }
  return c;
}

}  // namespace geodesic
