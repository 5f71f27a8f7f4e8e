#version 460
// Closest hit on a geodesic sphere: which one, and the arc length the intersection found.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "common/core.glsl"

layout(location = 0) rayPayloadInEXT ChartHit payload;
hitAttributeEXT float arcLength;

void main() {
  uint sphere = sphereRefs[gl_InstanceCustomIndexEXT + gl_PrimitiveID].sphere;
  payload = ChartHit(HIT_SPHERE, sphere, gl_HitTEXT, arcLength, vec2(0.0));
}
