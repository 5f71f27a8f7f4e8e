#version 460
// Nothing along this chart segment.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "common/core.glsl"

layout(location = 0) rayPayloadInEXT ChartHit payload;

void main() { payload.kind = HIT_NONE; }
