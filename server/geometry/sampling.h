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

// Phong lobe around the unit axis r with exponent e: density (e + 1) / (2 pi) cos^e(alpha),
// alpha the angle to r (directions below any surface included: the caller rejects them).
Vec3 sample_phong_lobe(const Vec3& r, double exponent, double u1, double u2);
double phong_lobe_pdf(const Vec3& r, double exponent, const Vec3& w);

// Uniform direction within angle acos(cos_max) of the unit axis: density 1 / (2 pi (1 -
// cos_max)). cos_max = -1 gives the whole sphere.
Vec3 sample_uniform_cone(const Vec3& axis, double cos_max, double u1, double u2);
double uniform_cone_pdf(const Vec3& axis, double cos_max, const Vec3& w);

// Uniform point of a triangle as barycentrics (b1, b2) of its second and third corners
// (density 2 in (b1, b2)), by the square-root warp.
struct Barycentrics {
  double b1 = 0;
  double b2 = 0;
};
Barycentrics sample_uniform_triangle(double u1, double u2);

// Unpolarised Fresnel reflectance of a dielectric interface for light arriving at cos_i > 0
// on the side of relative index eta = n_transmitted / n_incident; 1 under total internal
// reflection.
double fresnel_dielectric(double cos_i, double eta);

// Veach's power heuristic (beta = 2) weight of a strategy with density a against one with b.
double power_heuristic(double a, double b);

// Rec. 709 relative luminance of a linear RGB colour.
double luminance(const Vec3& rgb);

}  // namespace geodesic
