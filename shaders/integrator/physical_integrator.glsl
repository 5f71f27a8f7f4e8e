// The physical model: unbiased path tracing of the Riemannian rendering equation (eq. 2.4).
// At each vertex: emission (weighted against light sampling by the power heuristic when a
// smooth BSDF sample found it), next-event estimation towards one light sample (its last
// vertex uses light sampling alone), then a BSDF-sampled bounce; Russian roulette from the
// third bounce. max_depth counts bounces as in the paper's model: light reaches the camera
// over at most max_depth + 2 geodesic segments.
#ifndef PHYSICAL_INTEGRATOR_GLSL
#define PHYSICAL_INTEGRATOR_GLSL

#if defined(LIGHT_SAMPLING)
vec4 rng4(inout uint rng) { return vec4(rngNext(rng), rngNext(rng), rngNext(rng), rngNext(rng)); }

// Direct light at s by one light sample: f cos L / pdf, weighted against BSDF sampling.
vec3 nextEventEstimate(Surface s, LocalFrame local, vec3 n, vec3 wo, Material m, bool last,
                       inout uint rng) {
  LightSample ls;
  if (!sampleLight(s.position, s.geometricNormal, local, rng4(rng), ls)) return vec3(0.0);
  vec3 wi = toLocal(local, ls.direction);
  float cosI = dot(wi, n);
  if (cosI <= 0.0 || dot(ls.direction, s.geometricNormal) <= 0.0) return vec3(0.0);
  vec3 f = bsdfEval(m, n, wo, wi);
  if (max(f.r, max(f.g, f.b)) <= 0.0) return vec3(0.0);
  vec4 origin = offsetFromSurface(s.position, s.geometricNormal);
  // Stop short of an area light's own surface; a point light is not in the scene.
  float reach = ls.point ? ls.distance : ls.distance * (1.0 - 1e-4) - 1e-4;
  GeodesicRay shadow = GeodesicRay(origin, normalizeTangent(origin, ls.direction), s.cell, ~0u);
  if (reach > 0.0 && occluded(shadow, reach)) return vec3(0.0);
  float weight = ls.point || last ? 1.0 : powerHeuristic(ls.pdf, bsdfPdf(m, n, wo, wi));
  return f * cosI * ls.radiance * (weight / ls.pdf);
}
#endif

vec3 physicalRadiance(GeodesicRay ray, inout uint rng) {
  vec3 radiance = vec3(0.0), throughput = vec3(1.0);
  bool misWeighted = false;  // the last bounce was a smooth BSDF sample light sampling shares
  float bsdfDensity = 0.0;
  vec4 from = ray.p, heading = ray.v;  // the last vertex and the direction that left it
#if defined(LIGHT_SAMPLING)
  bool nee = frame.lightSampling == 0u && EMITTER_COUNT > 0u;
#else
  const bool nee = false;  // BSDF sampling alone: emission is found by hitting it
#endif
  for (uint depth = 0u; depth <= frame.maxDepth + 1u; ++depth) {
    ChartHit hit;
    float travelled;
    if (!followGeodesic(ray, FAR, false, hit, travelled)) break;  // escaped: black background
    Surface s = surfaceOf(ray, hit);
    Material m = materials[s.material];
    if (max(m.emission.r, max(m.emission.g, m.emission.b)) > 0.0) {
      float weight = 1.0;
#if defined(LIGHT_SAMPLING)
      if (misWeighted && s.emitter != ~0u) {
        float cosLight = abs(modelInner(s.incoming, s.geometricNormal));
        weight = powerHeuristic(bsdfDensity,
                                lightPdf(s.emitter, from, heading, travelled + s.t, cosLight));
      }
#endif
      radiance += throughput * m.emission.rgb * weight;
    }
    if (depth > frame.maxDepth) break;  // past the last bounce only emission counts
    LocalFrame local = localFrameAt(s.position);
    vec3 n = toLocal(local, s.normal);
    vec3 wo = -toLocal(local, s.incoming);
    bool last = depth == frame.maxDepth;
#if defined(LIGHT_SAMPLING)
    if (nee && hasSmoothLobe(m))
      radiance += throughput * nextEventEstimate(s, local, n, wo, m, last, rng);
#endif
    BsdfSample bs;
    if (!sampleBsdf(m, n, wo, s.frontFace, vec3(rngNext(rng), rngNext(rng), rngNext(rng)), bs))
      break;
    // After the last bounce light sampling alone covers the smooth lobes; delta lobes still
    // look for an emitter.
    if (last && nee && !bs.delta) break;
    vec4 side = bs.transmitted ? -s.geometricNormal : s.geometricNormal;
    vec4 direction = fromLocal(local, bs.wi);
    if (modelInner(direction, side) <= 0.0) break;  // below the geometric surface
    throughput *= bs.weight;
    misWeighted = nee && !bs.delta;
    bsdfDensity = bs.pdf;
    if (frame.russianRoulette != 0u && depth >= 3u && !survivesRussianRoulette(throughput, rng))
      break;
    from = s.position;
    vec4 origin = offsetFromSurface(s.position, side);
    heading = normalizeTangent(origin, direction);
    ray = GeodesicRay(origin, heading, s.cell, ~0u);
  }
  return radiance;
}

#endif
