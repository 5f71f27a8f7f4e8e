// Direct light from point lights: the paper's Riemannian local illumination (eq. 2.2) with
// the 0/1 shadow factor; the shadow ray follows the geodesic to the light through the cells.
#ifndef POINT_LIGHT_GLSL
#define POINT_LIGHT_GLSL
#if defined(HAS_POINT_LIGHTS)

// Diffuse and Phong specular terms of eq. 2.2, summed over visible point lights; n, ng and wo
// are in the local frame at the origin.
vec3 directIllumination(Surface s, LocalFrame frameAtHit, vec3 n, vec3 ng, vec3 wo, Material m) {
  vec3 sum = vec3(0.0);
  if (max(luminance(m.diffuse.rgb), luminance(m.specular.rgb)) <= 0.0) return sum;
  vec4 origin = offsetFromSurface(s.position, s.geometricNormal);
  for (uint i = 0u; i < POINT_LIGHT_COUNT; ++i) {
    vec4 lightPosition = lights[i].position;
    vec4 towards = geodesicDirection(s.position, lightPosition);
    if (dot(towards, towards) == 0.0) continue;  // on the light, or its antipode in S3
    vec3 wi = toLocal(frameAtHit, towards);
    float cosIncident = dot(wi, n);
    if (cosIncident <= 0.0 || dot(wi, ng) <= 0.0) continue;
    GeodesicRay shadow = GeodesicRay(origin, geodesicDirection(origin, lightPosition), s.cell, ~0u);
    if (occluded(shadow, geodesicDistance(origin, lightPosition))) continue;
    vec3 reflected = reflect(-wi, n);  // w_r = -w_i + 2 g(w_i, N) N
    float specular = pow(max(dot(reflected, wo), 0.0), m.specular.w);
    sum += lights[i].intensity.rgb * (m.diffuse.rgb * cosIncident + m.specular.rgb * specular);
  }
  return sum;
}

#endif

#endif
