#version 460
// Entry point 1: a compute kernel tracing with ray queries (fastest on lavapipe).
#extension GL_EXT_ray_query : require
#extension GL_GOOGLE_include_directive : require

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

#include "common/core.glsl"

const float FAR = 1e30;

// Procedural candidates are spheres; returns true if one was accepted.
void confirmSphereCandidate(rayQueryEXT q, Ray ray, float tMax) {
  uint primitive = rayQueryGetIntersectionPrimitiveIndexEXT(q, false);
  float t = intersectSphere(ray.origin, ray.direction, spheres[primitive].centerRadius,
                            rayQueryGetRayTMinEXT(q), tMax);
  if (t > 0.0) rayQueryGenerateIntersectionEXT(q, t);
}

Surface traceSurface(Ray ray) {
  ++tracedRays;
  rayQueryEXT q;
  rayQueryInitializeEXT(q, uScene, gl_RayFlagsOpaqueEXT, 0xFF, ray.origin, 0.0, ray.direction, FAR);
  while (rayQueryProceedEXT(q)) {
    if (rayQueryGetIntersectionTypeEXT(q, false) == gl_RayQueryCandidateIntersectionAABBEXT) {
      bool committed = rayQueryGetIntersectionTypeEXT(q, true) != gl_RayQueryCommittedIntersectionNoneEXT;
      confirmSphereCandidate(q, ray, committed ? rayQueryGetIntersectionTEXT(q, true) : FAR);
    }
  }
  uint type = rayQueryGetIntersectionTypeEXT(q, true);
  if (type == gl_RayQueryCommittedIntersectionNoneEXT) return noSurface();
  float t = rayQueryGetIntersectionTEXT(q, true);
  uint primitive = rayQueryGetIntersectionPrimitiveIndexEXT(q, true);
  if (type == gl_RayQueryCommittedIntersectionTriangleEXT)
    return triangleSurface(primitive, rayQueryGetIntersectionBarycentricsEXT(q, true), ray, t);
  return sphereSurface(primitive, ray, t);
}

bool traceOccluded(Ray ray, float maxDistance) {
  ++tracedRays;
  rayQueryEXT q;
  rayQueryInitializeEXT(q, uScene, gl_RayFlagsOpaqueEXT | gl_RayFlagsTerminateOnFirstHitEXT, 0xFF,
                        ray.origin, 0.0, ray.direction, maxDistance);
  while (rayQueryProceedEXT(q)) {
    if (rayQueryGetIntersectionTypeEXT(q, false) == gl_RayQueryCandidateIntersectionAABBEXT)
      confirmSphereCandidate(q, ray, maxDistance);
  }
  return rayQueryGetIntersectionTypeEXT(q, true) != gl_RayQueryCommittedIntersectionNoneEXT;
}

#include "integrator/integrator.glsl"

void main() { accumulatePixel(gl_GlobalInvocationID.xy); }
