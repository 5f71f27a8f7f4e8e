#version 460
// A shadow ray reached its light unblocked.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "entry/ray_tracing.glsl"

layout(location = PAYLOAD_SHADOW) rayPayloadInEXT uint shadowPayload;

void main() { shadowPayload = 0u; }
