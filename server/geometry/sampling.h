// Direction sampling in double precision: the reference twin of shaders/common/sampling.glsl.
#pragma once

#include "geometry/vec.h"

namespace geodesic {

// Two unit vectors completing the unit vector n to a right-handed orthonormal frame.
struct TangentFrame {
  Vec3 tangent;
  Vec3 bitangent;
};

// Duff et al. 2017, "Building an Orthonormal Basis, Revisited": branchless and stable for
// every n. Chooses the sign with n.z >= 0 (not copysign) exactly as orthonormalBasis does,
// so n.z = -0.0 gives the same frame in both.
TangentFrame orthonormal_basis(const Vec3& n);

// Cosine-weighted direction on the hemisphere around the unit normal n, from two uniform
// numbers in [0, 1): density cos(theta) / pi.
Vec3 sample_cosine_hemisphere(const Vec3& n, double u1, double u2);

// The density of sample_cosine_hemisphere at the unit direction w; zero below the surface.
// The shader never evaluates it because it cancels against the Lambertian BRDF.
double cosine_hemisphere_pdf(const Vec3& n, const Vec3& w);

// Rec. 709 relative luminance of a linear RGB colour.
double luminance(const Vec3& rgb);

}  // namespace geodesic
