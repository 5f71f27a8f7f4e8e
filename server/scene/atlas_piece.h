// A piece of a spherical Dirichlet domain charted apart (chart_atlas.h): its chart, its convex
// polyhedron there, and what each face is, so that the atlas can glue the faces.
#pragma once

#include <optional>
#include <vector>

#include "geometry/model.h"
#include "scene/group_orbit.h"
#include "scene/polyhedron.h"

namespace geodesic {

// The half-space <x, m> <= 0 in the gnomonic chart of `frame` (chart = (F x).xyz / (F x).w);
// nullopt when its plane is the chart's horizon.
inline std::optional<ChartPlane> chart_plane(const Mat4& frame, const Vec4& m) {
  const Vec4 q = frame * m;
  const double s = length(q.xyz());
  if (s < 1e-12) return std::nullopt;
  return ChartPlane{q.xyz() / s, -q.w / s};
}

struct AtlasWall {
  ChartPlane plane;
  bool internal;  // a wall towards the piece with centre `index`; else the bisector of the
                  // origin and element `index` (a face of the domain D)
  int index;
};

struct AtlasPiece {
  int centre;               // index of the piece's centre among the atlas' centres
  Mat4 frame;               // model -> the piece's frame (its centre to the origin)
  Polyhedron polyhedron;    // in that frame's gnomonic chart
  std::vector<AtlasWall> walls;  // one per face of the polyhedron
};

// When the bisector normals g o - o of every element span one 2-plane Pi (the group preserves
// a great circle, as L(p, +-1) and the mirrored lenses do), D is a lune: the join of the great
// circle C orthogonal to Pi with an arc of the circle in Pi. It is cut like an orange, by half
// great spheres through that arc at angles around C that the face pairings permute, into
// tetrahedra (and, where the arc is long, across it too): piece i's centre is centre i, and the
// pairings carry each piece's part of a face of D onto a whole face of another piece. nullopt
// when the normals do not span a 2-plane (projective space: the Voronoi cut of chart_atlas).
std::optional<std::vector<AtlasPiece>> lune_pieces(const std::vector<GroupElement>& elements,
                                                   double tolerance);

}  // namespace geodesic
