#version 460
// The ray left the scene. In E3 that is the end; quotient manifolds carry it across a face.
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "common/core.glsl"
#include "entry/ray_tracing.glsl"

layout(location = PAYLOAD_SURFACE) rayPayloadInEXT Surface surfacePayload;

void main() { surfacePayload = noSurface(); }
