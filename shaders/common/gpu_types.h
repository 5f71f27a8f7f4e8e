// Every struct the host writes and the shaders read, and the hit kinds and hit records both
// name: the one definition, compiled by the shaders (common/scene_data.glsl: std430 buffers,
// the std140 frame block, the push constants) and by the host (server/render/prepare/packed_scene.h,
// emitters.h, frame_uniforms.h: namespace geodesic::gpu, with vec4 / mat4 / uint as
// std::array<float, 4> / std::array<float, 16> column-major / uint32_t). Members are laid out
// so that C++ and std430/std140 agree (vec4s first, scalars after, padded to 16 bytes);
// tests/unit/gpu_layout_test.cpp holds each member's offset and each array's stride to what
// the shader compiler gives. Member names avoid GLSL's keywords and built-ins (smooth, clamp,
// sample).
#ifndef GEODESIC_GPU_TYPES_H
#define GEODESIC_GPU_TYPES_H

#ifdef __cplusplus
#include <array>
#include <cstdint>
namespace geodesic::gpu {
using vec4 = std::array<float, 4>;
using mat4 = std::array<float, 16>;  // column-major
using uint = std::uint32_t;
#endif

// What a chart segment hit (ChartHit.kind, integrator/chart_ray.glsl).
#define HIT_NONE 0u
#define HIT_TRIANGLE 1u
#define HIT_SPHERE 2u
#define HIT_TUBE 3u
#define HIT_SHAPE 4u  // an analytic shape of the shape table (primitives/shape_table.glsl)
// The hit record that a primitive kind's instances select in the ray-tracing pipeline's
// binding table (render/device/acceleration.cpp, ray_tracing_backend.cpp).
#define HIT_RECORD_TRIANGLES 0u
#define HIT_RECORD_SPHERES 1u
#define HIT_RECORD_SHAPES 2u

struct Material {
  vec4 ambient;       // rgb: k_a
  vec4 diffuse;       // rgb: k_d
  vec4 specular;      // rgb: k_s, w: shininess k_e
  vec4 mirror;        // rgb
  vec4 transmission;  // rgb: dielectric lobe weight, w: index of refraction
  vec4 emission;      // rgb: L_e
};

struct Sphere {
  vec4 center;    // model point
  float radius;   // geodesic
  uint material;
  uint emitter;   // index into the emitters, ~0u when it does not emit
  uint pad0;
};

// One sphere's bounding box in one cell's acceleration structure.
struct SphereRef {
  uint sphere;
  uint cell;
};

// An analytic shape (server/scene/shape.h): its kind (common/shape_kinds.h) and the model
// vectors and length its module reads (shaders/primitives/shapes/, server/scene/shapes/).
struct Shape {
  vec4 a;
  vec4 b;
  float size;
  uint kind;
  uint material;
  uint emitter;  // index into the emitters, ~0u when it does not emit (or is not sampled)
};

// One shape's bounding box in one cell's acceleration structure.
struct ShapeRef {
  uint shape;
  uint cell;
};

// The paper model's point lights.
struct PointLight {
  vec4 position;  // model point
  vec4 intensity;
};

struct TriangleInfo {
  uint material;
  uint smooth_normals;  // 1 when the mesh supplies per-vertex normals (E3)
  uint cell;
  uint emitter;  // index into the emitters, ~0u when it does not emit
};

// A light source of the physical model (server/render/prepare/emitters.h).
struct Emitter {
  vec4 center;    // model point: the light, the sphere's centre or the triangle's centroid;
                  // a horosphere's light-like l
  vec4 corner;    // triangle: first corner and two edges in the chart around the centroid
  vec4 edge1;
  vec4 edge2;
  vec4 radiance;  // rgb: intensity (point) or emitted radiance; w: model area
  uint kind;      // EmitterKind: 0 point, 1 sphere, 2 triangle, 3 horosphere
  float radius;   // sphere: geodesic radius; triangle: centroid to farthest corner
  float pmf;      // probability of choosing this emitter
  float cdf;      // sum of pmf up to and including this one
  uint image_begin;  // its images: light images [image_begin, image_begin + image_count)
  uint image_count;
  uint antipodal_pairs;  // point light, group holding -1: each image c stands for c and -c
  uint pad1;
};

// One image of an emitter under the group: the isometry (of the universal cover) and the
// emitter's centre carried by it, computed in double: all that light sampling reads of every
// image at every shading point.
struct LightImage {
  mat4 isometry;
  vec4 center;
};

// A cell of the chart atlas (server/render/prepare/cells.h).
struct Cell {
  mat4 chart_isometry;  // model -> the cell's frame
  // xyz: the corners of a chart box around everything the cell's segments trace (triangles,
  // spheres, shapes; not the edge tubes), padded; lo > hi when the cell holds none. A segment
  // that misses it skips the traversal (integrator/geodesic_tracer.glsl).
  vec4 content_lo;
  vec4 content_hi;
  // The same about its triangles alone, which a listed segment tests only when it meets it
  // (TRIANGLE_LIST: primitives/triangle_list.glsl).
  vec4 triangle_lo;
  vec4 triangle_hi;
  uint face_begin;
  uint face_count;
  uint tube_begin;  // its edge tubes: tubes [tube_begin, tube_begin + tube_count)
  uint tube_count;
  float tube_reach;  // the largest radius among them
  // Its tubes sorted by their two faces (CellFace.tubes), then those always tested:
  // tubes [tube_begin + always_begin, tube_begin + tube_count).
  uint always_begin;
  // Its sphere refs, sphere refs [sphere_begin, sphere_begin + sphere_count) (SPHERE_LIST).
  uint sphere_begin;
  uint sphere_count;
  // Its triangles as listed, listed [listed_begin, listed_begin + listed_count) (TRIANGLE_LIST;
  // none where the cell holds more than the list's limit).
  uint listed_begin;
  uint listed_count;
  uint listed_pairs;  // the first listed_pairs of them are parallelograms, the rest triangles
  // Its shape refs, shape refs [shape_begin, shape_begin + shape_count) (SHAPE_LIST).
  uint shape_begin;
  uint shape_count;
  // The first listed_hull_pairs of its pairs and listed_hull_lone of its lone triangles lie on
  // the scene's hull: no shadow segment crosses them (render/prepare/triangle_list.h).
  uint listed_hull_pairs;
  uint listed_hull_lone;
  uint pad0;
};

// What a segment of a cell that lists its triangles tests (TRIANGLE_LIST,
// server/render/prepare/triangle_list.h): a lone triangle (second = ~0u), by the watertight
// triangle test, or the parallelogram that two of the cell's triangles make, (a, b, c) and
// (a, c, d) with d = a + c - b, as one (geometry/parallelogram.glsl).
struct ListedPrimitive {
  uint triangle;  // the lone triangle, or the pair's first (a, b, c)
  uint second;    // the pair's second (a, c, d); ~0u for a lone triangle
};

// An edge tube: a capsule in its cell's chart (geometry/capsule.h, scene.h EdgeTube) and two
// local faces whose planes hold its axis (server/render/prepare/tube_culling.h; ~0u: always tested).
struct Tube {
  vec4 a;  // xyz: one end of the axis; w: chart radius
  vec4 b;  // xyz: the other end
  uint material;
  uint face_a;
  uint face_b;
  uint pad0;
};

struct CellFace {
  vec4 plane;    // xyz: outward unit normal in the cell's chart, w: offset (N . X = w)
  mat4 pairing;  // applied to a ray leaving through the face
  uint target_cell;
  uint partner;   // the face entered through
  uint internal;  // 1: a wall between pieces of one domain (not a crossing of MAX_CROSSINGS)
  // The cell's tubes whose first face this is, one per second face, in the order of their
  // second faces from local offset `tubes`; bit j of `tube_partners` set when one has second
  // face j (server/render/prepare/tube_culling.h): the tube on faces (this, j) is at `tubes` plus the
  // bits of tube_partners below j.
  uint tubes;
  uint tube_partners;
  uint pad0;
  uint pad1;
  uint pad2;
};

// The most light samples next-event estimation takes at one vertex (render.light_samples).
#define MAX_LIGHT_SAMPLES 8u
// The most images one emitter keeps (render/prepare/emitters.h: kMaxImagesPerEmitter).
#define MAX_EMITTER_IMAGES 64u

// The per-render uniform block (std140).
struct FrameUniforms {
  mat4 camera_pose;    // camera frame -> model isometry
  vec4 ambient_light;  // L_a
  float tan_half_fov_y;
  float aspect;
  uint width;
  uint height;
  uint max_depth;
  uint light_count;
  uint seed;
  uint russian_roulette;  // 0 or 1
  uint max_crossings;     // cell faces a ray may cross
  uint camera_cell;
  uint lighting;        // 0 paper, 1 physical (LightingModel)
  uint light_sampling;  // LightSampling: 0 MIS, 1 BSDF sampling alone, 2 light sampling alone
  uint emitter_count;
  float light_cutoff;     // geodesic distance (1e30: none)
  float clamp_luminance;  // largest sample luminance; 0: no clamp
  uint light_samples;     // next-event estimates per vertex, 1 .. MAX_LIGHT_SAMPLES
};

// Which samples one dispatch adds, [start, start + count), to which pixels: a rectangle of
// column_count x row_count from (column_offset, row_offset) (the push constants). A pass over
// a large image is split into slices (render/service/pass_slicer.h) so that the render thread can turn
// to a camera move or another session in between.
struct SampleRange {
  uint start;
  uint count;
  uint column_offset;
  uint row_offset;
  uint column_count;
  uint row_count;
};

#ifdef __cplusplus
static_assert(sizeof(Material) == 96 && sizeof(Sphere) == 32 && sizeof(SphereRef) == 8 &&
              sizeof(PointLight) == 32 && sizeof(TriangleInfo) == 16 && sizeof(Emitter) == 112 &&
              sizeof(LightImage) == 80 && sizeof(Cell) == 192 && sizeof(Tube) == 48 &&
              sizeof(CellFace) == 112 && sizeof(FrameUniforms) == 144 &&
              sizeof(SampleRange) == 24,
              "a 16-byte multiple for every array element, std140's for the frame");
}  // namespace geodesic::gpu
#endif

#endif
