#version 460
// Closest hit on an analytic shape: which one, and the arc length the intersection found.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "common/core.glsl"

layout(location = 0) rayPayloadInEXT ChartHit payload;
hitAttributeEXT float arcLength;

void main() {
  uint shape = shapeRefs[gl_InstanceCustomIndexEXT + gl_PrimitiveID].shape;
  payload = ChartHit(HIT_SHAPE, shape, gl_HitTEXT, arcLength, vec2(0.0));
}
