// Descriptor layout and GPU structs shared by every entry point; mirrors
// server/render/packed_scene.h and server/render/frame_uniforms.h (std430 / std140), which
// tests/unit/gpu_layout_test.cpp holds to the compiled layout; binding numbers from
// common/bindings.h. A buffer is declared only when the pipeline's features read it
// (server/render/pipeline_features.cpp decides the same, binding by binding).
#ifndef SCENE_DATA_GLSL
#define SCENE_DATA_GLSL

#include "common/bindings.h"

struct Material {
  vec4 ambient;   // k_a
  vec4 diffuse;   // k_d
  vec4 specular;  // k_s, w = shininess k_e
  vec4 mirror;
  vec4 transmission;  // dielectric lobe weight, w = index of refraction
  vec4 emission;  // L_e
};

struct Sphere {
  vec4 center;  // model point
  float radius;  // geodesic
  uint material;
  uint emitter;  // index into emitters, ~0u when it does not emit
  uint pad0;
};

// One sphere's bounding box in one cell's acceleration structure.
struct SphereRef {
  uint sphere;
  uint cell;
};

struct PointLight {
  vec4 position;  // model point
  vec4 intensity;
};

struct TriangleInfo {
  uint material;
  uint smoothNormals;
  uint cell;
  uint emitter;  // index into emitters, ~0u when it does not emit
};

// A cell of the chart atlas (server/render/cells.h).
// A light source of the physical model (server/render/emitters.h).
struct Emitter {
  vec4 center;    // model point: light, sphere centre or triangle centroid
  vec4 corner;    // triangle: first corner and two edges in the chart around the centroid
  vec4 edge1;
  vec4 edge2;
  vec4 radiance;  // rgb: intensity (point) or emitted radiance; w: model area
  uint kind;      // 0 point, 1 sphere, 2 triangle
  float radius;   // sphere: geodesic radius; triangle: centroid to farthest corner
  float pmf;
  float cdf;
  uint imageBegin;  // its images: lightImages[imageBegin, imageBegin + imageCount)
  uint imageCount;
  uint pad0, pad1;
};

// One image of an emitter (server/render/emitters.h GpuLightImage).
struct LightImage {
  mat4 isometry;
  vec4 center;  // isometry * the emitter's centre
};

struct Cell {
  mat4 chartIsometry;  // model -> the cell's frame
  uint faceBegin;
  uint faceCount;
  uint tubeBegin;  // its edge tubes: tubes[tubeBegin, tubeBegin + tubeCount)
  uint tubeCount;
  float tubeReach;  // the largest radius among them
  uint alwaysBegin;  // tubes[tubeBegin + alwaysBegin, tubeBegin + tubeCount): always tested
  uint sphereBegin;  // its sphere refs: sphereRefs[sphereBegin, sphereBegin + sphereCount)
  uint sphereCount;
};

// An edge tube: a capsule in its cell's chart (geometry/capsule.h) and two local faces whose
// planes hold its axis (server/render/tube_culling.h; ~0u: always tested).
struct Tube {
  vec4 a;  // xyz: one end of the axis; w: chart radius
  vec4 b;  // xyz: the other end
  uint material;
  uint faceA, faceB;
  uint pad0;
};

struct CellFace {
  vec4 plane;    // xyz: outward unit normal in the cell's chart, w: offset (N . X = w)
  mat4 pairing;  // applied to a ray leaving through the face
  uint targetCell;
  uint partner;  // the face entered through
  uint internal;  // 1: a wall between pieces of one domain (not a crossing of MAX_CROSSINGS)
  uint tubes;     // the cell's tubes whose first face this is: local offset | count << 16
};

layout(set = 0, binding = BINDING_SCENE) uniform accelerationStructureEXT uScene;
// Two halves of width * height pixels each: even- and odd-numbered samples (sum rgb, count a).
layout(set = 0, binding = BINDING_ACCUMULATION, std430)
    buffer Accumulation { vec4 accumulation[]; };
// Frame.lightSampling: LightSampling (server/scene/scene.h) as frame_uniforms.h packs it.
const uint LIGHT_SAMPLING_MIS = 0u;
const uint LIGHT_SAMPLING_BSDF = 1u;
const uint LIGHT_SAMPLING_LIGHT = 2u;
layout(set = 0, binding = BINDING_FRAME, std140) uniform Frame {
  mat4 cameraPose;    // camera frame -> model isometry
  vec4 ambientLight;  // L_a
  float tanHalfFovY;
  float aspect;
  uint width;
  uint height;
  uint maxDepth;
  uint lightCount;
  uint seed;
  uint russianRoulette;
  uint maxCrossings;
  uint cameraCell;
  uint lighting;       // 0 paper, 1 physical
  uint lightSampling;  // LIGHT_SAMPLING_MIS, _BSDF (BSDF sampling alone) or _LIGHT (NEE alone)
  uint emitterCount;
  float lightCutoff;   // geodesic distance
  float clampLuminance;  // 0: no clamp
  uint pad0;
} frame;
layout(set = 0, binding = BINDING_MATERIALS, std430)
    readonly buffer Materials { Material materials[]; };
// Rays traced per pixel (camera, bounce and shadow segments), for rays/s figures.
layout(set = 0, binding = BINDING_RAY_COUNTS, std430) buffer RayCounts { uint rayCounts[]; };
// Samples dropped because they were NaN or infinite (tests require none), and the tracer's
// counters since the last clear: face crossings, and rays cut off at MAX_CROSSINGS.
layout(set = 0, binding = BINDING_DIAGNOSTICS, std430) buffer Diagnostics {
  uint nonFiniteSamples;
  uint crossedFacesTotal;
  uint truncatedRaysTotal;
};
#if defined(HAS_SPHERES)
layout(set = 0, binding = BINDING_SPHERES, std430) readonly buffer Spheres { Sphere spheres[]; };
layout(set = 0, binding = BINDING_SPHERE_REFS, std430)
    readonly buffer SphereRefs { SphereRef sphereRefs[]; };
#endif
#if defined(HAS_TRIANGLES)
layout(set = 0, binding = BINDING_POSITIONS, std430)  // chart
    readonly buffer Positions { vec4 positions[]; };
layout(set = 0, binding = BINDING_INDICES, std430) readonly buffer Indices { uint indices[]; };
layout(set = 0, binding = BINDING_TRIANGLES, std430)
    readonly buffer Triangles { TriangleInfo triangles[]; };
#endif
#if defined(HAS_SMOOTH_NORMALS)
layout(set = 0, binding = BINDING_NORMALS, std430)  // E3
    readonly buffer Normals { vec4 normals[]; };
#endif
#if defined(LIGHTING_PAPER) && defined(HAS_POINT_LIGHTS)
layout(set = 0, binding = BINDING_LIGHTS, std430) readonly buffer Lights { PointLight lights[]; };
#endif
#if defined(CELL_CROSSING) || defined(MULTIPLE_CHARTS)
layout(set = 0, binding = BINDING_CELLS, std430) readonly buffer Cells { Cell cells[]; };
#endif
#if defined(CELL_CROSSING)
layout(set = 0, binding = BINDING_CELL_FACES, std430)
    readonly buffer CellFaces { CellFace cellFaces[]; };
#endif
#if defined(HAS_TUBES)
layout(set = 0, binding = BINDING_TUBES, std430) readonly buffer Tubes { Tube tubes[]; };
#endif
#if defined(LIGHT_SAMPLING)
layout(set = 0, binding = BINDING_EMITTERS, std430)
    readonly buffer Emitters { Emitter emitters[]; };
layout(set = 0, binding = BINDING_LIGHT_IMAGES, std430)
    readonly buffer LightImages { LightImage lightImages[]; };
#endif

// Loop bounds a specialised pipeline bakes in as constants; the all-features pipeline reads
// them from the frame.
#if !defined(POINT_LIGHT_COUNT)
#define POINT_LIGHT_COUNT frame.lightCount
#endif
#if !defined(EMITTER_COUNT)
#define EMITTER_COUNT frame.emitterCount
#endif
#if !defined(MAX_CROSSINGS)
#define MAX_CROSSINGS frame.maxCrossings
#endif
// A bound on walls between pieces crossed in one trace: a lune of L(p, 1) has p pieces around
// one edge (scene/atlas_piece.h).
#define MAX_WALL_CROSSINGS (1024u + 8u * MAX_CROSSINGS)

// Which samples this dispatch adds, [sampleStart, sampleStart + sampleCount), to which pixels:
// a rectangle of columnCount x rowCount from (columnOffset, rowOffset). SampleRange in
// server/render/frame_uniforms.h.
layout(push_constant) uniform Push {
  uint sampleStart;
  uint sampleCount;
  uint columnOffset;
  uint rowOffset;
  uint columnCount;
  uint rowCount;
} push;

// Rays traced by this invocation so far; the entry points' trace functions count into it.
uint tracedRays = 0u;
// Faces crossed (walls included) and rays given up at MAX_CROSSINGS by this invocation.
uint crossedFaces = 0u;
uint truncatedRays = 0u;

#endif
