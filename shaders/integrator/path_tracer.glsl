// Camera samples and accumulation: one geodesic per sample through the pinhole, traced by
// the scene's lighting model (paper or physical), summed into the even/odd halves.
#ifndef PATH_TRACER_GLSL
#define PATH_TRACER_GLSL

// One sample of pixel `pixel`: a camera geodesic through the pinhole at `jitter` in the pixel,
// its other dimensions drawn from `samples`.
vec3 pixelSample(uvec2 pixel, vec2 jitter, PathSampler samples) {
  vec2 ndc = 2.0 * (vec2(pixel) + jitter) / vec2(frame.width, frame.height) - 1.0;
  vec3 dir = normalize(vec3(ndc.x * frame.tan_half_fov_y * frame.aspect, -ndc.y * frame.tan_half_fov_y, -1.0));
  GeodesicRay ray;
  ray.p = frame.camera_pose * originPoint();
  ray.v = frame.camera_pose * vec4(dir, 0.0);
  ray.cell = frame.camera_cell;
  ray.enteredFace = ~0u;
#if defined(LIGHTING_PAPER) && defined(LIGHTING_PHYSICAL)
  return frame.lighting == 0u ? paperRadiance(ray, samples) : physicalRadiance(ray, samples);
#elif defined(LIGHTING_PAPER)
  return paperRadiance(ray, samples);
#else
  return physicalRadiance(ray, samples);
#endif
}

// Adds push.count samples to the pixel's running sums (rgb) and counts (a), kept in two
// halves, even- and odd-numbered samples: their difference estimates the remaining error.
void accumulatePixel(uvec2 launch) {
  if (launch.x >= push.column_count || launch.y >= push.row_count) return;
  uvec2 pixel = launch + uvec2(push.column_offset, push.row_offset);
  if (pixel.x >= frame.width || pixel.y >= frame.height) return;
  uint index = pixel.y * frame.width + pixel.x;
  vec4 halves[2] = vec4[2](vec4(0.0), vec4(0.0));
  for (uint i = 0u; i < push.count; ++i) {
    uint sampleIndex = push.start + i;
    // Every dimension of the path, the position in the pixel first, is a scrambled Sobol
    // sequence per pixel and half (common/sampler.glsl).
    PathSampler samples = pathSampler(index, sampleIndex);
    vec3 value = pixelSample(pixel, samplePair(samples, 0u), samples);
    // A NaN/Inf sample would poison the pixel forever: drop its value, and count it.
    if (any(isnan(value)) || any(isinf(value))) {
      atomicAdd(nonFiniteSamples, 1u);
      value = vec3(0.0);
    }
    // The optional firefly clamp (biased, off by default): cap one sample's luminance.
    float level = luminance(value);
    if (frame.clamp_luminance > 0.0 && level > frame.clamp_luminance)
      value *= frame.clamp_luminance / level;
    halves[sampleIndex & 1u] += vec4(value, 1.0);
  }
  accumulation[index] += halves[0];
  accumulation[index + frame.width * frame.height] += halves[1];
  rayCounts[index] += tracedRays;
  if (crossedFaces != 0u) atomicAdd(crossedFacesTotal, crossedFaces);
  if (truncatedRays != 0u) atomicAdd(truncatedRaysTotal, truncatedRays);
}

#endif
