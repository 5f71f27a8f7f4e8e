// Scattering for the paper's materials: a Lambertian lobe (albedo k_d) sampled by cosine, and
// a perfect mirror. One lobe is chosen per bounce in proportion to its reflectance.
#ifndef PAPER_MATERIAL_GLSL
#define PAPER_MATERIAL_GLSL

// Samples the next direction; returns false when the material reflects nothing. `weight` is
// f_r * cos / pdf for the sampled direction.
bool sampleBounce(Surface s, vec3 incoming, Material m, inout uint rng, out vec3 direction,
                  out vec3 weight) {
  float mirror = luminance(m.mirror.rgb);
  float diffuse = luminance(m.diffuse.rgb);
  if (mirror + diffuse <= 0.0) return false;
  float pMirror = mirror / (mirror + diffuse);
  if (rngNext(rng) < pMirror) {
    direction = reflectDirection(s.position, incoming, s.normal);
    weight = m.mirror.rgb / pMirror;
  } else {
    direction = sampleCosineHemisphere(s.normal, vec2(rngNext(rng), rngNext(rng)));
    weight = m.diffuse.rgb / (1.0 - pMirror);  // (k_d / pi) * cos / (cos / pi)
  }
  return metricDot(s.position, direction, s.geometricNormal) > 0.0;
}

#endif
