// Descriptor layout shared by every entry point: the structs from common/gpu_types.h and the
// binding numbers from common/bindings.h, both compiled by the host too
// (tests/unit/gpu_layout_test.cpp holds the host to the compiled layout). A buffer is declared
// only when the pipeline's features read it (server/render/prepare/pipeline_features.cpp decides the
// same, binding by binding).
#ifndef SCENE_DATA_GLSL
#define SCENE_DATA_GLSL

#include "common/bindings.h"
#include "common/gpu_types.h"

layout(set = 0, binding = BINDING_SCENE) uniform accelerationStructureEXT uScene;
// Two halves of width * height pixels each: even- and odd-numbered samples (sum rgb, count a).
layout(set = 0, binding = BINDING_ACCUMULATION, std430)
    buffer Accumulation { vec4 accumulation[]; };
// frame.light_sampling: LightSampling (server/scene/scene.h) as the host packs it.
const uint LIGHT_SAMPLING_MIS = 0u;
const uint LIGHT_SAMPLING_BSDF = 1u;
const uint LIGHT_SAMPLING_LIGHT = 2u;
layout(set = 0, binding = BINDING_FRAME, std140) uniform Frame { FrameUniforms frame; };
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
#if defined(HAS_SHAPES)
layout(set = 0, binding = BINDING_SHAPES, std430) readonly buffer Shapes { Shape shapes[]; };
layout(set = 0, binding = BINDING_SHAPE_REFS, std430)
    readonly buffer ShapeRefs { ShapeRef shapeRefs[]; };
#endif
#if defined(HAS_TRIANGLES)
layout(set = 0, binding = BINDING_POSITIONS, std430)  // chart
    readonly buffer Positions { vec4 positions[]; };
layout(set = 0, binding = BINDING_INDICES, std430) readonly buffer Indices { uint indices[]; };
layout(set = 0, binding = BINDING_TRIANGLES, std430)
    readonly buffer Triangles { TriangleInfo triangles[]; };
#endif
#if defined(TRIANGLE_LIST)
layout(set = 0, binding = BINDING_LISTED, std430)
    readonly buffer Listed { ListedPrimitive listed[]; };
#endif
#if defined(HAS_SMOOTH_NORMALS)
layout(set = 0, binding = BINDING_NORMALS, std430)  // E3
    readonly buffer Normals { vec4 normals[]; };
#endif
#if defined(LIGHTING_PAPER) && defined(HAS_POINT_LIGHTS)
layout(set = 0, binding = BINDING_LIGHTS, std430) readonly buffer Lights { PointLight lights[]; };
#endif
// READS_CELLS: segments read cell records, to cross faces, to pick a cell's chart, or for the
// spheres and triangles a cell lists (defined by the host: PipelineFeatures::reads_cells).
#if defined(READS_CELLS)
layout(set = 0, binding = BINDING_CELLS, std430) readonly buffer Cells { Cell cells[]; };
#endif
#if defined(CELL_CROSSING)
layout(set = 0, binding = BINDING_CELL_FACES, std430)
    readonly buffer CellFaces { CellFace cellFaces[]; };
// Face f's plane, for the passes over every face of a cell, whose indices are constants once
// unrolled: in a one-cell space baked in (FACE_PLANES, pipeline_features.h face_planes). Not
// for an index that differs between lanes: a constant array read so goes lane by lane.
#if defined(FACE_PLANES)
const vec4 facePlanes[] = vec4[](FACE_PLANES);
vec4 facePlane(uint f) { return facePlanes[f]; }
#else
vec4 facePlane(uint f) { return cellFaces[f].plane; }
#endif
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
#define POINT_LIGHT_COUNT frame.light_count
#endif
#if !defined(EMITTER_COUNT)
#define EMITTER_COUNT frame.emitter_count
#endif
#if !defined(MAX_CROSSINGS)
#define MAX_CROSSINGS frame.max_crossings
#endif
// The most images of any one emitter: the size of light sampling's array of image weights.
#if !defined(EMITTER_IMAGES)
#define EMITTER_IMAGES MAX_EMITTER_IMAGES
#endif
// A bound on walls between pieces crossed in one trace: a lune of L(p, 1) has p pieces around
// one edge (scene/atlas_piece.h).
#define MAX_WALL_CROSSINGS (1024u + 8u * MAX_CROSSINGS)

// Which samples this dispatch adds, to which pixels (SampleRange).
layout(push_constant) uniform Push { SampleRange push; };

// Chart segments followed by this invocation so far (integrator/geodesic_tracer.glsl), whether
// traversed or turned away by their cell's content box.
uint tracedRays = 0u;
// Faces crossed (walls included) and rays given up at MAX_CROSSINGS by this invocation.
uint crossedFaces = 0u;
uint truncatedRays = 0u;

#endif
