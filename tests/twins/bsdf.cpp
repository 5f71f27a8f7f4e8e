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

BsdfValue bsdf_evaluate(const Material& m, const Vec3& n, const Vec3& wo, const Vec3& wi) {
  const double cos_i = dot(wi, n);
  if (cos_i <= 0 || dot(wo, n) <= 0) return {};
  // The normalised Phong lobe's value is its density times (e + 2) / (e + 1).
  const double phong = phong_lobe_pdf(reflect_about(wo, n), m.shininess, wi);
  const LobeChoice p = lobe_probabilities(m);
  return {kInvPi * m.diffuse + phong * (m.shininess + 2) / (m.shininess + 1) * m.specular,
          p.diffuse * kInvPi * cos_i + p.specular * phong};
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
    const BsdfValue value = bsdf_evaluate(m, n, wo, s.wi);
    s.pdf = value.pdf;
    if (s.pdf <= 0) return std::nullopt;
    s.weight = (dot(s.wi, n) / s.pdf) * value.f;
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
