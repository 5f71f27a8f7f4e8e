#version 460
// Entry point 1: a compute kernel tracing with ray queries (fastest on lavapipe).
#extension GL_EXT_ray_query : require
#extension GL_GOOGLE_include_directive : require

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

#include "common/core.glsl"
#include "primitives/sphere_candidate.glsl"

// The closest (or, for shadows, any) hit along the chart segment o + s d, s in [0, sMax], in
// the given cell; (p, v) is the same ray in the cell's frame.
ChartHit traceChart(vec3 o, vec3 d, float sMax, uint cell, vec4 p, vec4 v, bool anyHit) {
  ++tracedRays;
  rayQueryEXT q;
  uint flags = gl_RayFlagsOpaqueEXT | (anyHit ? gl_RayFlagsTerminateOnFirstHitEXT : 0u);
  rayQueryInitializeEXT(q, uScene, flags, 1u << cell, o, 0.0, d, sMax);
  ChartHit best = noChartHit();
  while (rayQueryProceedEXT(q)) {
    if (rayQueryGetIntersectionTypeEXT(q, false) != gl_RayQueryCandidateIntersectionAABBEXT)
      continue;
    uint refIndex = rayQueryGetIntersectionInstanceCustomIndexEXT(q, false) +
                    rayQueryGetIntersectionPrimitiveIndexEXT(q, false);
    bool committed = rayQueryGetIntersectionTypeEXT(q, true) != gl_RayQueryCommittedIntersectionNoneEXT;
    float sLimit = committed ? rayQueryGetIntersectionTEXT(q, true) : sMax;
    float s, t;
    if (sphereCandidate(sphereRefs[refIndex], p, v, 0.0, sLimit, s, t)) {
      rayQueryGenerateIntersectionEXT(q, s);
      best = ChartHit(2u, sphereRefs[refIndex].sphere, s, t, vec2(0.0));
    }
  }
  uint type = rayQueryGetIntersectionTypeEXT(q, true);
  if (type == gl_RayQueryCommittedIntersectionNoneEXT) return noChartHit();
  if (type == gl_RayQueryCommittedIntersectionTriangleEXT)
    return ChartHit(1u,
                    rayQueryGetIntersectionInstanceCustomIndexEXT(q, true) +
                        rayQueryGetIntersectionPrimitiveIndexEXT(q, true),
                    rayQueryGetIntersectionTEXT(q, true), FAR,
                    rayQueryGetIntersectionBarycentricsEXT(q, true));
  return best;  // the last generated sphere hit is the committed one
}

#include "integrator/integrator.glsl"

void main() { accumulatePixel(gl_GlobalInvocationID.xy); }
