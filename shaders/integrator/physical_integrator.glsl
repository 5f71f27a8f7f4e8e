// The physical model: unbiased path tracing of the Riemannian rendering equation (eq. 2.4).
// At each vertex: emission (weighted against light sampling by the power heuristic when a
// smooth BSDF sample found it), next-event estimation by frame.light_samples light samples
// (its last vertex uses light sampling alone), then a BSDF-sampled bounce; Russian roulette
// from the third bounce. max_depth counts bounces as in the paper's model: light reaches the
// camera over at most max_depth + 2 geodesic segments.
#ifndef PHYSICAL_INTEGRATOR_GLSL
#define PHYSICAL_INTEGRATOR_GLSL

#if defined(LIGHT_SAMPLING)
// True when something lies between the surface and the light point. The shadow geodesic
// starts off the surface and aims at the light point itself (from the shifted start the
// sample's own direction and distance would reach past a sphere's silhouette, or into a
// nearby area light), stopping short of an area light by its own surface offset.
bool occludedTowards(Surface s, LightSample ls) {
  vec4 origin = offsetFromSurface(s.position, s.geometricNormal);
  vec4 direction = geodesicDirection(origin, ls.position);
  float distance = geodesicDistance(origin, ls.position);
#if defined(GEOMETRY_SPHERICAL)
  if (ls.distance > PI) {  // the long way round: the light point's own geodesic, not the short one
    direction = -direction;
    distance = FULL_TURN - distance;
  }
#endif
  if (dot(direction, direction) == 0.0) return false;
  float reach = ls.point ? distance : distance - surfaceOffsetLength(ls.position);
#if defined(HAS_SPHERE_EMITTERS)
  // A sphere's surface where this geodesic meets it, as traversal will find it: the light
  // point itself comes from a geodesic that may be long (H3 chords lose 0.05 over 10 units).
  if (ls.sphereRadius > 0.0) {
    float surface = intersectGeodesicSphere(origin, direction, ls.sphereCenter, ls.sphereRadius, 0.0, FAR);
    if (surface > 0.0) reach = surface - surfaceOffsetLength(ls.position);
  }
#endif
#if defined(HAS_HOROSPHERE_EMITTERS)
  if (ls.horosphere.w > 0.0) {  // likewise a horosphere's
    float surface = intersectHorosphere(origin, direction, ls.horosphere, 0.0, FAR);
    if (surface < FAR) reach = surface - surfaceOffsetLength(ls.position);
  }
#endif
  GeodesicRay shadow = GeodesicRay(origin, direction, s.cell, ~0u);
  return reach > 0.0 && occluded(shadow, reach);
}

// Direct light at s by frame.light_samples light samples of one emitter: their mean f cos L /
// pdf, each weighted against BSDF sampling (the power heuristic with the light strategy's
// sample count, Veach's n_i p_i) unless light sampling alone is asked for. The samples share the
// emitter and the walk over its images (chooseImages); sample k takes the pixel's point on the
// light rotated by k steps of the R2 sequence, uniform on its own. A point light's sample is
// its image's alone: one the choice repeats (they come in order) is not traced again.
vec3 nextEventEstimate(Surface s, LocalFrame local, vec3 n, vec3 wo, Material m, bool last,
                       bool lightOnly, PathSampler samples, uint depth) {
#if defined(HAS_SPHERE_EMITTERS) || defined(HAS_TRIANGLE_EMITTERS) || \
    defined(HAS_HOROSPHERE_EMITTERS)
  vec2 onLight = bounceSample(samples, depth, PAIR_LIGHT_POINT);
#else
  const vec2 onLight = vec2(0.0);  // point lights have no extent to sample
#endif
  if (EMITTER_COUNT == 0u) return vec3(0.0);
  vec2 choice = bounceSample(samples, depth, PAIR_LIGHT_CHOICE);
  Emitter e = emitters[chooseEmitter(choice.x)];
  uint images[MAX_LIGHT_SAMPLES], branches[MAX_LIGHT_SAMPLES];
  float choices[MAX_LIGHT_SAMPLES];
  float count = float(frame.light_samples);
  uint chosen = chooseImages(e, s.position, s.geometricNormal, choice.y, frame.light_samples,
                             images, branches, choices);
#if defined(HAS_POINT_LIGHTS)
  bool point = e.kind == EMITTER_POINT;
#else
  const bool point = false;  // no point lights: every sample is traced
#endif
  vec3 sum = vec3(0.0), previous = vec3(0.0);
  for (uint k = 0u; k < chosen; ++k) {
    if (point && k > 0u && images[k] == images[k - 1u] && branches[k] == branches[k - 1u]) {
      sum += previous;
      continue;
    }
    previous = vec3(0.0);
    vec2 rotated = fract(onLight + float(k) * vec2(0.7548776662, 0.5698402910));
    LightSample ls;
    if (!sampleLightImage(e, images[k], branches[k], choices[k], s.position, s.geometricNormal,
                          local, rotated, ls))
      continue;
    vec3 wi = toLocal(local, ls.direction);
    float cosI = dot(wi, n);
    if (cosI <= 0.0 || modelInner(ls.direction, s.geometricNormal) <= 0.0) continue;
    BsdfValue bsdf = bsdfEvaluate(m, n, wo, wi);
    if (max(bsdf.f.r, max(bsdf.f.g, bsdf.f.b)) <= 0.0) continue;
    if (occludedTowards(s, ls)) continue;
    float weight = ls.point || last || lightOnly ? 1.0 : powerHeuristic(count * ls.pdf, bsdf.pdf);
    previous = bsdf.f * cosI * ls.radiance * (weight / (count * ls.pdf));
    sum += previous;
  }
  return sum;
}
#endif

vec3 physicalRadiance(GeodesicRay ray, PathSampler samples) {
  vec3 radiance = vec3(0.0), throughput = vec3(1.0);
  bool misWeighted = false;  // the last bounce was a smooth BSDF sample light sampling shares
  float bsdfDensity = 0.0;
  vec4 from = ray.p, heading = ray.v;  // the last vertex and the direction that left it
#if defined(LIGHT_SAMPLING)
  bool nee = frame.light_sampling != LIGHT_SAMPLING_BSDF && EMITTER_COUNT > 0u;
  bool lightOnly = frame.light_sampling == LIGHT_SAMPLING_LIGHT;
#else
  const bool nee = false;  // BSDF sampling alone: emission is found by hitting it
#endif
  for (uint depth = 0u; depth <= frame.max_depth + 1u; ++depth) {
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
        float density = lightPdf(s.emitter, from, heading, travelled + s.t, cosLight);
        // Light sampling alone, or past the last bounce, where the NEE sample took this segment
        // with full weight: what it can sample is its own (a copy past the cutoff is not).
        weight = lightOnly || depth > frame.max_depth
                     ? (density > 0.0 ? 0.0 : 1.0)
                     : powerHeuristic(bsdfDensity, float(frame.light_samples) * density);
      }
#endif
      radiance += throughput * m.emission.rgb * weight;
    }
    if (depth > frame.max_depth) break;  // past the last bounce only emission counts
    if (s.horizon) break;                // too far out to go on from (primitives/surface.glsl)
    LocalFrame local = localFrameAt(s.position);
    vec3 n = toLocal(local, s.normal);
    vec3 wo = -toLocal(local, s.incoming);
    bool last = depth == frame.max_depth;
#if defined(LIGHT_SAMPLING)
    if (nee && hasSmoothLobe(m))
      radiance += throughput * nextEventEstimate(s, local, n, wo, m, last, lightOnly, samples, depth);
#endif
    vec2 direction2 = bounceSample(samples, depth, PAIR_DIRECTION);
    vec2 lobeRoulette = bounceSample(samples, depth, PAIR_LOBE_ROULETTE);
    BsdfSample bs;
    if (!sampleBsdf(m, n, wo, s.frontFace, vec3(lobeRoulette.x, direction2), bs)) break;
    // After the last bounce light sampling alone covers the smooth lobes; delta lobes still
    // look for an emitter, and so do smooth ones where some emission is beyond light sampling
    // (UNSAMPLED_EMISSION, render/prepare/pipeline_features.h).
#if !defined(UNSAMPLED_EMISSION)
    if (last && nee && !bs.delta) break;
#endif
    vec4 side = bs.transmitted ? -s.geometricNormal : s.geometricNormal;
    vec4 direction = fromLocal(local, bs.wi);
    if (modelInner(direction, side) <= 0.0) break;  // below the geometric surface
    throughput *= bs.weight;
    misWeighted = nee && !bs.delta;
    bsdfDensity = bs.pdf;
    // From the third bounce: from the first, as Cycles does, paths are 15-20 % cheaper but the
    // Cornell box's relMSE doubles: error per second gets worse (docs/benchmarks.md).
    if (frame.russian_roulette != 0u && depth >= 3u &&
        !survivesRussianRoulette(throughput, lobeRoulette.y))
      break;
    from = s.position;
    vec4 origin = offsetFromSurface(s.position, side);
    heading = normalizeTangent(origin, direction);
    ray = GeodesicRay(origin, heading, s.cell, ~0u);
  }
  return radiance;
}

#endif
