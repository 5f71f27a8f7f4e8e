// The model volume of a convex polyhedron given in the chart (a fundamental domain's volume is
// its manifold's: 2 pi^2 / |Gamma| in S3, the hyperbolic volume in H3).
#pragma once

#include "geometry/model.h"
#include "scene/polyhedron.h"

namespace geodesic {

// The polyhedron must contain the chart origin. Each face triangle is coned to the origin and
// the radial integral done in closed form (the chart's volume density is (1 - K |X|^2)^-2), so
// only a smooth 2-D integral over the triangle is left to Gauss quadrature: relative error
// below 1e-12 for the domains of the catalogue.
double domain_volume(GeometryKind kind, const Polyhedron& p);

}  // namespace geodesic
