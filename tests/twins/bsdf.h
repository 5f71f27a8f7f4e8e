// The `physical` lighting model's scattering in double precision: the reference twin of
// shaders/materials/bsdf.glsl. A material is a mix of four lobes whose weights sum to at most
// one per channel (the loader checks it), so every material conserves energy:
//   diffuse       Lambert, f = k_d / pi
//   specular      normalised Phong, f = k_s (e + 2) / (2 pi) cos^e(alpha), alpha the angle
//                 between w_i and the mirror direction of w_o (Lafortune and Willems 1994)
//   mirror        perfect specular reflection with reflectance k_m
//   transmission  a smooth dielectric of index `ior` with weight k_t: Fresnel reflection, or
//                 refraction (radiance scaled by 1 / eta^2)
// Everything is in the local frame at the origin (vectors point away from the surface); n is
// the shading normal on the side of w_o.
#pragma once

#include <optional>

#include "geometry/vec.h"
#include "scene/scene.h"

namespace geodesic {

struct LobeChoice {
  double diffuse = 0, specular = 0, mirror = 0, transmission = 0;  // sum to 1 (or all 0)
};

// Probabilities of sampling each lobe: proportional to the luminance of its weight.
LobeChoice lobe_probabilities(const Material& m);

// f_r(w_o, w_i) of the non-delta lobes (diffuse and specular), zero unless both directions
// lie above the surface, and the density (solid angle) with which sample_bsdf returns w_i
// through them: one evaluation, as next-event estimation and BSDF sampling use both.
struct BsdfValue {
  Vec3 f;
  double pdf = 0;
};
BsdfValue bsdf_evaluate(const Material& m, const Vec3& n, const Vec3& wo, const Vec3& wi);

struct BsdfSample {
  Vec3 wi;
  Vec3 weight;       // f cos / pdf; for a delta lobe its reflectance over the lobe's probability
  double pdf = 0;    // solid-angle density (0 for a delta lobe)
  bool delta = false;
  bool transmitted = false;  // crossed the surface
};

// One direction from the mixture (u0 picks the lobe, u1 and u2 the direction). `entering` is
// true when w_o lies on the outer side of the surface (its outward normal faces w_o). Empty when
// the material scatters nothing or the direction falls below the surface.
std::optional<BsdfSample> sample_bsdf(const Material& m, const Vec3& n, const Vec3& wo,
                                      bool entering, double u0, double u1, double u2);

}  // namespace geodesic
