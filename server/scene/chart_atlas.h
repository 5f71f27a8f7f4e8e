// Spherical quotients whose group preserves a great circle (L(p, +-1), projective space, the
// mirrored lenses) have no fundamental domain inside an open hemisphere, which is all that one
// gnomonic chart shows. Their Dirichlet domain D is cut into convex pieces, each charted around
// its own centre, and glued by the identity across the walls between pieces and by the group
// across D's faces: an atlas of cells the renderer walks as it walks S3's tesseract.
//
// A lune (every bisector normal in one 2-plane) is cut like an orange (atlas_piece.h). Otherwise
// D is cut by the Voronoi cells of a Gamma-invariant set S of chart centres (Gamma applied to an
// orthonormal frame +-f_i of R4): every Voronoi cell V_s lies within pi/3 of its centre s (S
// contains +-f_i), so each piece D n V_s is a convex polyhedron in the chart centred on s; and
// since Gamma permutes S, g^-1 carries the part of D's face of g inside V_s exactly onto the
// part of its partner face inside V_{g^-1 s}. A mirror r is also the Voronoi wall between s and
// r s: the piece on D's side keeps r's face, glued to itself, and r s gets no piece.
#pragma once

#include <vector>

#include "scene/group_orbit.h"
#include "scene/manifold.h"

namespace geodesic {

// `elements`: the whole finite group (identity first, trivial stabiliser of the origin); D is
// its Dirichlet domain around the origin. Returns the manifold with `pieces` filled, `faces`
// D's faces, `domain` empty. Throws SceneError ("generators: ...") when more pieces would be
// needed than the renderer keeps (1024 lune pieces; 256 Voronoi pieces of up to 256 faces), a
// piece's face has no partner, or a pairing misses its partner face by more than 100 x
// `tolerance`.
Manifold chart_atlas_manifold(const std::vector<GroupElement>& elements, double tolerance);

}  // namespace geodesic
