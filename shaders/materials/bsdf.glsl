// The physical model's scattering: diffuse, normalised Phong, mirror and dielectric lobes
// weighted by the material; the float twin of tests/twins/bsdf.cpp (read its header for the
// definitions). Vectors are in the local frame at the origin and point away from the surface;
// n is the shading normal on the side of wo.
#ifndef BSDF_GLSL
#define BSDF_GLSL

struct LobeChoice {
  float diffuse, specular, mirror, transmission;
};

LobeChoice lobeProbabilities(Material m) {
  LobeChoice c = LobeChoice(luminance(m.diffuse.rgb), luminance(m.specular.rgb),
                            luminance(m.mirror.rgb), luminance(m.transmission.rgb));
  float total = c.diffuse + c.specular + c.mirror + c.transmission;
  if (total <= 0.0) return LobeChoice(0.0, 0.0, 0.0, 0.0);
  return LobeChoice(c.diffuse / total, c.specular / total, c.mirror / total,
                    c.transmission / total);
}

// True when some lobe is not a delta: next-event estimation can reach it.
bool hasSmoothLobe(Material m) { return max(luminance(m.diffuse.rgb), luminance(m.specular.rgb)) > 0.0; }

vec3 reflectAbout(vec3 w, vec3 n) { return 2.0 * dot(w, n) * n - w; }

// f_r(wo, wi) of the smooth lobes (diffuse and specular) and the density with which
// sampleBsdf returns wi through them, in one pass: next-event estimation (its MIS weight) and
// a BSDF sample each need both for the same direction, and they share the cosine tests and
// the Phong power: the normalised lobe's value is its density times (e + 2) / (e + 1).
struct BsdfValue {
  vec3 f;
  float pdf;  // solid angle
};

BsdfValue bsdfEvaluate(Material m, vec3 n, vec3 wo, vec3 wi) {
  float cosI = dot(wi, n);
  if (cosI <= 0.0 || dot(wo, n) <= 0.0) return BsdfValue(vec3(0.0), 0.0);
  float exponent = m.specular.w;
  float phong = phongLobePdf(reflectAbout(wo, n), exponent, wi);
  LobeChoice p = lobeProbabilities(m);
  return BsdfValue(
      m.diffuse.rgb / PI + phong * (exponent + 2.0) / (exponent + 1.0) * m.specular.rgb,
      p.diffuse * cosI / PI + p.specular * phong);
}

struct BsdfSample {
  vec3 wi;
  vec3 weight;  // f cos / pdf
  float pdf;    // 0 for a delta lobe
  bool delta;
  bool transmitted;
};

// False when nothing scatters or the direction falls below the surface. `entering`: wo is on
// the outer side of the surface.
bool sampleBsdf(Material m, vec3 n, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  LobeChoice p = lobeProbabilities(m);
  float cosO = dot(wo, n);
  s = BsdfSample(vec3(0.0), vec3(0.0), 0.0, false, false);
  if (cosO <= 0.0) return false;
  if (u.x < p.diffuse + p.specular) {
    s.wi = u.x < p.diffuse ? sampleCosineHemisphere(n, u.yz)
                           : samplePhongLobe(reflectAbout(wo, n), m.specular.w, u.yz);
    BsdfValue value = bsdfEvaluate(m, n, wo, s.wi);
    s.pdf = value.pdf;
    if (s.pdf <= 0.0) return false;
    s.weight = value.f * (dot(s.wi, n) / s.pdf);
    return true;
  }
  s.delta = true;
  if (u.x < p.diffuse + p.specular + p.mirror) {
    s.wi = reflectAbout(wo, n);
    s.weight = m.mirror.rgb / p.mirror;
    return true;
  }
#if defined(HAS_TRANSMISSION)
  if (p.transmission <= 0.0) return false;
  // Dielectric: reflect with the Fresnel probability F, else refract; F cancels in the weight.
  float eta = entering ? m.transmission.w : 1.0 / m.transmission.w;
  float fresnel = fresnelDielectric(cosO, eta);
  float v = (u.x - (p.diffuse + p.specular + p.mirror)) / p.transmission;
  s.weight = m.transmission.rgb / p.transmission;
  if (v < fresnel) {
    s.wi = reflectAbout(wo, n);
    return true;
  }
  float cosT = sqrt(max(0.0, 1.0 - (1.0 - cosO * cosO) / (eta * eta)));
  s.wi = normalize(-wo / eta + (cosO / eta - cosT) * n);
  s.weight /= eta * eta;
  s.transmitted = true;
  return true;
#else
  return false;
#endif
}

#endif
