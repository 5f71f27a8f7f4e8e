#version 460
// Closest hit on a triangle: which one, where on it.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "common/core.glsl"

layout(location = 0) rayPayloadInEXT ChartHit payload;
hitAttributeEXT vec2 barycentrics;

void main() {
  payload = ChartHit(HIT_TRIANGLE, gl_InstanceCustomIndexEXT + gl_PrimitiveID, gl_HitTEXT, FAR, barycentrics);
}
