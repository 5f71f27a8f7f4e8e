// Descriptor layout and GPU structs shared by every entry point; mirrors
// server/render/packed_scene.h and server/render/frame_uniforms.h (std430 / std140).
#ifndef SCENE_DATA_GLSL
#define SCENE_DATA_GLSL

struct Material {
  vec4 ambient;   // k_a
  vec4 diffuse;   // k_d
  vec4 specular;  // k_s, w = shininess k_e
  vec4 mirror;
  vec4 emission;  // L_e
};

struct Sphere {
  vec4 centerRadius;
  uint material;
  uint pad0, pad1, pad2;
};

struct PointLight {
  vec4 position;
  vec4 intensity;
};

struct TriangleInfo {
  uint material;
  uint smoothNormals;
};

layout(set = 0, binding = 0) uniform accelerationStructureEXT uScene;
layout(set = 0, binding = 1, std430) buffer Accumulation { vec4 accumulation[]; };
layout(set = 0, binding = 2, std140) uniform Frame {
  mat4 cameraPose;    // camera frame -> world isometry
  vec4 ambientLight;  // L_a
  float tanHalfFovY;
  float aspect;
  uint width;
  uint height;
  uint maxDepth;
  uint lightCount;
  uint seed;
  uint russianRoulette;  // 0 or 1
} frame;
layout(set = 0, binding = 3, std430) readonly buffer Spheres { Sphere spheres[]; };
layout(set = 0, binding = 4, std430) readonly buffer Materials { Material materials[]; };
layout(set = 0, binding = 5, std430) readonly buffer Lights { PointLight lights[]; };
layout(set = 0, binding = 6, std430) readonly buffer Positions { vec4 positions[]; };
layout(set = 0, binding = 7, std430) readonly buffer Normals { vec4 normals[]; };
layout(set = 0, binding = 8, std430) readonly buffer Indices { uint indices[]; };
layout(set = 0, binding = 9, std430) readonly buffer Triangles { TriangleInfo triangles[]; };
// Rays traced per pixel (camera, bounce and shadow rays), for rays/s figures.
layout(set = 0, binding = 10, std430) buffer RayCounts { uint rayCounts[]; };

// Rays traced by this invocation so far; the entry points' trace functions count into it.
uint tracedRays = 0u;

// Which samples this dispatch adds: [sampleStart, sampleStart + sampleCount).
layout(push_constant) uniform Push {
  uint sampleStart;
  uint sampleCount;
} push;

#endif
