// Direct light from point lights: the paper's Riemannian local illumination (eq. 2.2) with
// the 0/1 shadow factor. Needs traceOccluded() from the entry point.
#ifndef POINT_LIGHT_GLSL
#define POINT_LIGHT_GLSL

// Diffuse and Phong specular terms of eq. 2.2, summed over visible point lights.
vec3 directIllumination(Surface s, vec3 wo, Material m) {
  vec3 sum = vec3(0.0);
  if (max(luminance(m.diffuse.rgb), luminance(m.specular.rgb)) <= 0.0) return sum;
  vec3 origin = offsetFromSurface(s.position, s.geometricNormal);
  for (uint i = 0u; i < frame.lightCount; ++i) {
    vec3 lightPosition = lights[i].position.xyz;
    vec3 wi = geodesicDirection(s.position, lightPosition);
    float cosIncident = metricDot(s.position, wi, s.normal);
    if (cosIncident <= 0.0 || metricDot(s.position, wi, s.geometricNormal) <= 0.0) continue;
    float distance = geodesicDistance(origin, lightPosition);
    if (traceOccluded(Ray(origin, wi), distance)) continue;
    vec3 wr = -reflectDirection(s.position, wi, s.normal);  // perfect reflection of w_i
    float specular = pow(max(metricDot(s.position, wr, wo), 0.0), m.specular.w);
    sum += lights[i].intensity.rgb * (m.diffuse.rgb * cosIncident + m.specular.rgb * specular);
  }
  return sum;
}

#endif
