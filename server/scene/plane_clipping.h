// The convex polyhedron a large set of candidate planes cuts out, built incrementally because
// make_polyhedron is quartic in the plane count: Dirichlet domains have thousands of candidate
// bisectors and only a few dozen faces.
#pragma once

#include <cstddef>
#include <vector>

#include "scene/polyhedron.h"

namespace geodesic {

struct ClippedPolyhedron {
  Polyhedron polyhedron;  // bounded == false: the planes never closed it within `horizon`
  std::vector<int> kept;  // indices into the candidates of the planes that bound a face
};

// `candidates` must be sorted by delta, nearest first. Planes are added while the polyhedron is
// open (unbounded, or with a vertex at chart radius >= horizon: the Klein ball's rim in H3),
// then whenever one cuts off a vertex, until the next plane lies beyond every vertex; planes
// that no longer bound a face are dropped as it shrinks. Gives up (unbounded) after max_kept
// planes, or after kMaxClips planes that cut it (each a rebuild): in H3 a cell of infinite
// volume reaches past the rim, where every bisector of the ball cuts it again, and a ball of
// 10^5 elements cost 10^5 rebuilds (24 s for one generator text a fuzzer found). The domains of
// the catalogue, the Curved Spaces files and the tests need 190 at most. Checks the thread's
// preparation budget (scene/preparation_budget.h) before each rebuild.
inline constexpr int kMaxClips = 1024;
ClippedPolyhedron clip_planes(const std::vector<ChartPlane>& candidates, double tolerance,
                              double horizon, std::size_t max_kept);

}  // namespace geodesic
