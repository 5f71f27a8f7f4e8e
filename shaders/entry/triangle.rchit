#version 460
// Closest hit on a triangle: the surface record for shading.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "common/core.glsl"
#include "entry/ray_tracing.glsl"

layout(location = PAYLOAD_SURFACE) rayPayloadInEXT Surface surfacePayload;
hitAttributeEXT vec2 barycentrics;

void main() {
  Ray ray = Ray(gl_WorldRayOriginEXT, gl_WorldRayDirectionEXT);
  surfacePayload = triangleSurface(gl_PrimitiveID, barycentrics, ray, gl_HitTEXT);
}
