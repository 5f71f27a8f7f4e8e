// The Dirichlet domain of a group Gamma of isometries around a base point b:
//   D = { x : d(x, b) <= d(x, g b) for every g in Gamma },
// a convex polyhedron bounded by the bisectors of b and its nearest images. The face of D on
// the bisector of b and g b is carried by g^-1 onto the face of g^-1 (both lie on the bisector
// of b and g^-1 b after the move), so g^-1 is that face's pairing: a manifold (or orbifold,
// when g is a reflection) ready for the renderer, from nothing but generators.
//
// The group is enumerated breadth-first over words in the generators and their inverses, in
// order of displacement d(b, g b), until every element that could cut the cell (displacement
// at most twice the cell's circumradius) is known. In H3 the domain may have ideal vertices on
// the sphere at infinity, the tips of cusps (a knot complement's): finite volume, not compact.
// Such a cell is complete once its face pairings generate the group (each generator, applied
// to b, walks back to b across the cell's faces); a cell that reaches the sphere in more than
// points has infinite volume and is refused. Each product is re-orthonormalised in the
// model's form, so the O(3,1) round-off that compounds along long words in H3 stays at one
// product's worth; `product_drift` reports the error that re-orthonormalisation removed.
//
// The renderer charts the domain around the origin, so the base point is moved there (the
// generators are conjugated by the translation taking b to the origin). The default base point
// is the origin, moved when it is fixed by a group element (its bisector would be undefined)
// and, in S3, when the domain does not fit the gnomonic chart's open hemisphere.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/model.h"
#include "geometry/vec.h"
#include "scene/manifold.h"

namespace geodesic {

struct DirichletOptions {
  std::optional<Vec3> base_point;  // exponential coordinates at the origin
  double tolerance = 1e-9;         // for make_polyhedron and validate_manifold
  std::size_t max_elements = 200000;
};

struct DirichletDomain {
  Manifold manifold;            // validated (or its chart pieces checked face by face)
  Vec3 base_point;              // the base point used (exponential coordinates), now the origin:
                                // the generators were conjugated by the translation from it
  std::size_t elements = 0;     // group elements enumerated
  bool finite = false;          // every element was found (the group order is `elements`)
  double inradius = 0;          // distance from the base point to the nearest face
  double circumradius = 0;      // ... to the farthest finite vertex
  int cusps = 0;                // H3: classes of ideal vertices (manifold.h cusps())
  double volume = 0;            // of the domain: the manifold's volume
  double product_drift = 0;     // largest isometry_error / |g|^2 of a product before re-orthonormalising
  double isometry_error = 0;    // largest isometry_error of a face pairing
  double seconds = 0;           // wall time of the whole construction
};

// In S3, a group whose every domain crosses the chart's horizon (it preserves a great circle:
// projective space, L(p, +-1), mirrored lenses) gets its domain cut into pieces charted apart
// (scene/chart_atlas.h). Throws SceneError ("generators: reason") when the group is too large
// to enumerate, leaves the domain unbounded (a non-compact quotient in E3 and S3, one of infinite
// volume in H3), needs more chart pieces
// than the renderer has cells, or when the result fails validate_manifold.
DirichletDomain dirichlet_domain(GeometryKind kind, const std::vector<Mat4>& generators,
                                 const DirichletOptions& options = {});

}  // namespace geodesic
