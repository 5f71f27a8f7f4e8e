// Payloads shared by the ray-tracing pipeline's stages.
#ifndef RAY_TRACING_GLSL
#define RAY_TRACING_GLSL
#define PAYLOAD_SURFACE 0
#define PAYLOAD_SHADOW 1
#define MISS_SURFACE 0
#define MISS_SHADOW 1
#endif
