#include "twins/bsdf.h"

#include <cmath>
#include <numbers>

#include "geometry/sampling.h"

namespace geodesic {
namespace {

constexpr double kInvPi = 1 / std::numbers::pi;

Vec3 reflect_about(const Vec3& w, const Vec3& n) { return 2 * dot(w, n) * n - w; }

}  // namespace

LobeChoice lobe_probabilities(const Material& m) {
  LobeChoice c{luminance(m.diffuse), luminance(m.specular), luminance(m.mirror),
               luminance(m.transmission)};
  const double total = c.diffuse + c.specular + c.mirror + c.transmission;
  if (total <= 0) return {};
  return {c.diffuse / total, c.specular / total, c.mirror / total, c.transmission / total};
}

Vec3 bsdf_eval(const Material& m, const Vec3& n, const Vec3& wo, const Vec3& wi) {
  if (dot(wi, n) <= 0 || dot(wo, n) <= 0) return {};
  const double cos_alpha = dot(reflect_about(wo, n), wi);
  const double phong = cos_alpha <= 0 ? 0
                                      : (m.shininess + 2) / (2 * std::numbers::pi) *
                                            std::pow(cos_alpha, m.shininess);
  return kInvPi * m.diffuse + phong * m.specular;
}

double bsdf_pdf(const Material& m, const Vec3& n, const Vec3& wo, const Vec3& wi) {
  if (dot(wi, n) <= 0 || dot(wo, n) <= 0) return 0;
  const LobeChoice p = lobe_probabilities(m);
  return p.diffuse * cosine_hemisphere_pdf(n, wi) +
         p.specular * phong_lobe_pdf(reflect_about(wo, n), m.shininess, wi);
}

std::optional<BsdfSample> sample_bsdf(const Material& m, const Vec3& n, const Vec3& wo,
                                      bool entering, double u0, double u1, double u2) {
  const LobeChoice p = lobe_probabilities(m);
  const double cos_o = dot(wo, n);
  if (cos_o <= 0) return std::nullopt;
  BsdfSample s;
  if (u0 < p.diffuse + p.specular) {
    s.wi = u0 < p.diffuse ? sample_cosine_hemisphere(n, u1, u2)
                          : sample_phong_lobe(reflect_about(wo, n), m.shininess, u1, u2);
    s.pdf = bsdf_pdf(m, n, wo, s.wi);
    if (s.pdf <= 0) return std::nullopt;
    s.weight = (dot(s.wi, n) / s.pdf) * bsdf_eval(m, n, wo, s.wi);
    return s;
  }
  s.delta = true;
  if (u0 < p.diffuse + p.specular + p.mirror) {
    s.wi = reflect_about(wo, n);
    s.weight = (1 / p.mirror) * m.mirror;
    return s;
  }
  if (p.transmission <= 0) return std::nullopt;
  // Dielectric: reflect with the Fresnel probability F, else refract; F cancels in the weight.
  const double eta = entering ? m.ior : 1 / m.ior;
  const double fresnel = fresnel_dielectric(cos_o, eta);
  const double u = (u0 - (p.diffuse + p.specular + p.mirror)) / p.transmission;
  s.weight = (1 / p.transmission) * m.transmission;
  if (u < fresnel) {
    s.wi = reflect_about(wo, n);
    return s;
  }
  const double cos_t = std::sqrt(std::max(0.0, 1 - (1 - cos_o * cos_o) / (eta * eta)));
  s.wi = normalize((-1 / eta) * wo + (cos_o / eta - cos_t) * n);
  s.weight = (1 / (eta * eta)) * s.weight;
  s.transmitted = true;
  return s;
}

}  // namespace geodesic
