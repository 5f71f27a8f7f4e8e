// The paper's model (Novello et al. 2019, algorithms 2 and 3): at each hit emission, the
// ambient term and direct light from point lights (eq. 2.2), then one Monte Carlo bounce, up
// to depth d.
#ifndef PAPER_INTEGRATOR_GLSL
#define PAPER_INTEGRATOR_GLSL

vec3 paperRadiance(GeodesicRay ray, PathSampler samples) {
  vec3 radiance = vec3(0.0);
  vec3 throughput = vec3(1.0);
  for (uint depth = 0u; depth <= frame.max_depth; ++depth) {
    ChartHit hit;
    float travelled;
    if (!followGeodesic(ray, FAR, false, hit, travelled)) break;  // escaped: black background
    Surface s = surfaceOf(ray, hit);
    Material m = materials[s.material];
    radiance += throughput * (m.emission.rgb + m.ambient.rgb * frame.ambient_light.rgb);
    if (s.horizon) break;  // too far out to light or go on from (primitives/surface.glsl)
    LocalFrame local = localFrameAt(s.position);
    vec3 n = toLocal(local, s.normal), ng = toLocal(local, s.geometricNormal);
    vec3 incoming = toLocal(local, s.incoming);
#if defined(HAS_POINT_LIGHTS)
    radiance += throughput * directIllumination(s, local, n, ng, -incoming, m);
#endif
    if (depth == frame.max_depth) break;
    vec2 lobeRoulette = bounceSample(samples, depth, PAIR_LOBE_ROULETTE);
    vec3 direction, weight;
    if (!sampleBounce(n, ng, incoming, m, lobeRoulette.x,
                      bounceSample(samples, depth, PAIR_DIRECTION), direction, weight))
      break;
    throughput *= weight;
    if (frame.russian_roulette != 0u && depth >= 1u &&
        !survivesRussianRoulette(throughput, lobeRoulette.y))
      break;
    vec4 origin = offsetFromSurface(s.position, s.geometricNormal);
    ray = GeodesicRay(origin, normalizeTangent(origin, fromLocal(local, direction)), s.cell, ~0u);
  }
  return radiance;
}

#endif
