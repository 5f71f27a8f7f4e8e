#version 460
// Closest hit on an analytic sphere: the surface record for shading.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "common/core.glsl"
#include "entry/ray_tracing.glsl"

layout(location = PAYLOAD_SURFACE) rayPayloadInEXT Surface surfacePayload;

void main() {
  Ray ray = Ray(gl_WorldRayOriginEXT, gl_WorldRayDirectionEXT);
  surfacePayload = sphereSurface(gl_PrimitiveID, ray, gl_HitTEXT);
}
