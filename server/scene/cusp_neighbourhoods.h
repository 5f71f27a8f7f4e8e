// Horoball neighbourhoods of the cusps of a cusped H3 domain (dirichlet_domain.h): one
// horosphere per ideal vertex, the same horoball seen from each vertex of a cusp's class, so
// that the renderer, which draws the domain's objects in every copy, shows each cusp cut off by
// one embedded horosphere tiling (its torus, or Klein bottle, of images).
//
// A horoball is {x : <x, l> > -1} for a light-like l aimed at its ideal point (shapes/
// horosphere.cpp); a face pairing g carries the one at vertex c onto the one at g c, l -> g l.
// Two horoballs are disjoint when <l1, l2> <= -2. The size: the horoballs of all cusps grown
// alike until two of them (at the domain's vertices, or one and its image under a word of at
// most two face pairings) touch, then shrunk by `margin` (a distance into the cusp), and
// further if need be to keep them at least `clearance` from the origin (the domain's centre,
// where the default camera stands).
#pragma once

#include <vector>

#include "geometry/vec.h"
#include "scene/manifold.h"

namespace geodesic {

struct CuspHorosphere {
  int cusp = 0;        // index into cusps(kind, m)
  int vertex = 0;      // the domain's ideal vertex
  Vec3 direction;      // unit, towards the vertex (the horosphere's "direction")
  double distance = 0; // signed distance from the origin (the horosphere's "distance")
};

// The area of the horosphere {<x, l> = -1} within the domain, where the faces through its
// ideal point alone cut it (the cross-section of an embedded cusp neighbourhood: the ideal
// vertex's share of the cusp torus). The horosphere is flat: x0 + u + |u|^2 / 2 l, x0 its
// point nearest the origin and u tangent to it, and each face through the ideal point is a
// line in u. Infinity where those faces do not bound it (no faces; a horosphere at no ideal
// vertex, whose images are dense).
double horosphere_area_in_domain(const Manifold& m, const Vec4& l);

// Throws SceneError when a cusp is incomplete (going round it scales its horospheres: the
// pairings' cusp holonomy is not Euclidean). Empty for a compact domain.
std::vector<CuspHorosphere> cusp_horospheres(const Manifold& m, double margin = 0.25,
                                             double clearance = 0.5);

}  // namespace geodesic
