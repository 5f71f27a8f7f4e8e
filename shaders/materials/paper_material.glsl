// Scattering for the paper's materials, in the local frame: a Lambertian lobe (albedo k_d)
// sampled by cosine, and a perfect mirror, one chosen per bounce in proportion to its
// reflectance.
#ifndef PAPER_MATERIAL_GLSL
#define PAPER_MATERIAL_GLSL

// Samples the next direction from the uniforms `lobe` (mirror or diffuse) and `u` (the
// direction); false when the material reflects nothing. `weight` is f_r * cos / pdf for the
// sampled direction.
bool sampleBounce(vec3 n, vec3 ng, vec3 incoming, Material m, float lobe, vec2 u,
                  out vec3 direction, out vec3 weight) {
  float mirror = luminance(m.mirror.rgb);
  float diffuse = luminance(m.diffuse.rgb);
  if (mirror + diffuse <= 0.0) return false;
  float pMirror = mirror / (mirror + diffuse);
  if (lobe < pMirror) {
    direction = reflect(incoming, n);
    weight = m.mirror.rgb / pMirror;
  } else {
    direction = sampleCosineHemisphere(n, u);
    weight = m.diffuse.rgb / (1.0 - pMirror);  // (k_d / pi) * cos / (cos / pi)
  }
  return dot(direction, ng) > 0.0;
}

#endif
