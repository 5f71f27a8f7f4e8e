// Spherical quotients whose group preserves a great circle (L(p, +-1), projective space, the
// mirrored lenses) have no fundamental domain inside an open hemisphere, which is all that one
// gnomonic chart shows. Their Dirichlet domain D is cut instead by the Voronoi cells of a
// Gamma-invariant set S of chart centres (Gamma applied to an orthonormal frame +-f_i of R4):
// every Voronoi cell V_s lies within pi/3 of its centre s (S contains +-f_i), so each piece
// D n V_s is a convex polyhedron in the chart centred on s; and since Gamma permutes S, g^-1
// carries the part of D's face of g inside V_s exactly onto the part of its partner face inside
// V_{g^-1 s}. Pieces are glued to each other by the identity along Voronoi faces and by the
// group across D's faces: an atlas of cells the renderer walks as it walks S3's tesseract.
#pragma once

#include <vector>

#include "scene/group_orbit.h"
#include "scene/manifold.h"

namespace geodesic {

// `elements`: the whole finite group (identity first, trivial stabiliser of the origin); D is
// its Dirichlet domain around the origin. Returns the manifold with `pieces` filled, `faces`
// D's faces, `domain` empty. A mirror's pieces are glued to themselves. Throws SceneError
// ("generators: ...") when more than 256 pieces, or a piece of more than 256 faces, would be
// needed (L(p, 1) past p of about 150), a piece's face has no partner, or a pairing misses its
// partner face by more than 100 x `tolerance`.
Manifold chart_atlas_manifold(const std::vector<GroupElement>& elements, double tolerance);

}  // namespace geodesic
