// The paper's algorithms 2 and 3: a camera geodesic per sample, then at each hit emission,
// the ambient term and direct light (eq. 2.2), and one Monte Carlo bounce, up to depth d.
#ifndef PATH_TRACER_GLSL
#define PATH_TRACER_GLSL

vec3 pathRadiance(GeodesicRay ray, inout uint rng) {
  vec3 radiance = vec3(0.0);
  vec3 throughput = vec3(1.0);
  for (uint depth = 0u; depth <= frame.maxDepth; ++depth) {
    ChartHit hit;
    if (!followGeodesic(ray, FAR, false, hit)) break;  // escaped: the background is black
    Surface s = surfaceOf(ray, hit);
    Material m = materials[s.material];
    LocalFrame local = localFrameAt(s.position);
    vec3 n = toLocal(local, s.normal), ng = toLocal(local, s.geometricNormal);
    vec3 incoming = toLocal(local, s.incoming);
    radiance += throughput * (m.emission.rgb + m.ambient.rgb * frame.ambientLight.rgb +
                              directIllumination(s, local, n, ng, -incoming, m));
    if (depth == frame.maxDepth) break;
    vec3 direction, weight;
    if (!sampleBounce(n, ng, incoming, m, rng, direction, weight)) break;
    throughput *= weight;
    if (frame.russianRoulette != 0u && depth >= 1u) {
      // Survive with probability q and divide by it: unbiased, and dim paths end early.
      float q = min(1.0, max(throughput.r, max(throughput.g, throughput.b)));
      if (rngNext(rng) >= q) break;
      throughput /= q;
    }
    vec4 origin = offsetFromSurface(s.position, s.geometricNormal);
    ray = GeodesicRay(origin, normalizeTangent(origin, fromLocal(local, direction)), s.cell, ~0u);
  }
  return radiance;
}

// One sample of pixel `pixel`: a jittered camera geodesic through the pinhole.
vec3 pixelSample(uvec2 pixel, inout uint rng) {
  vec2 jitter = vec2(rngNext(rng), rngNext(rng));
  vec2 ndc = 2.0 * (vec2(pixel) + jitter) / vec2(frame.width, frame.height) - 1.0;
  vec3 dir = normalize(vec3(ndc.x * frame.tanHalfFovY * frame.aspect, -ndc.y * frame.tanHalfFovY, -1.0));
  GeodesicRay ray;
  ray.p = frame.cameraPose * originPoint();
  ray.v = frame.cameraPose * vec4(dir, 0.0);
  ray.cell = frame.cameraCell;
  ray.enteredFace = ~0u;
  return pathRadiance(ray, rng);
}

// Adds push.sampleCount samples to the pixel's running sums (rgb) and counts (a), kept in two
// halves, even- and odd-numbered samples: their difference estimates the remaining error.
void accumulatePixel(uvec2 launch) {
  uvec2 pixel = uvec2(launch.x, launch.y + push.rowOffset);
  if (pixel.x >= frame.width || launch.y >= push.rowCount || pixel.y >= frame.height) return;
  uint index = pixel.y * frame.width + pixel.x;
  vec4 halves[2] = vec4[2](vec4(0.0), vec4(0.0));
  for (uint i = 0u; i < push.sampleCount; ++i) {
    uint sampleIndex = push.sampleStart + i;
    uint rng = rngSeed(index, sampleIndex, frame.seed);
    vec3 value = pixelSample(pixel, rng);
    // A NaN/Inf sample would poison the pixel forever: drop its value, and count it.
    if (any(isnan(value)) || any(isinf(value))) {
      atomicAdd(nonFiniteSamples, 1u);
      value = vec3(0.0);
    }
    halves[sampleIndex & 1u] += vec4(value, 1.0);
  }
  accumulation[index] += halves[0];
  accumulation[index + frame.width * frame.height] += halves[1];
  rayCounts[index] += tracedRays;
}

#endif
