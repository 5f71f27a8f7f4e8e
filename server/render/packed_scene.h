// The scene flattened into the arrays the shaders read (layouts match
// shaders/common/scene_data.glsl, std430): model-space spheres and lights, and for every cell
// of the chart atlas its triangles and edge tubes (in the cell's chart) and sphere bounding
// boxes. Pure data:
// built and tested without a device.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "render/cells.h"
#include "render/emitters.h"
#include "render/spatial_order.h"
#include "scene/scene.h"

namespace geodesic {

using Float4 = std::array<float, 4>;
using Float16 = std::array<float, 16>;

struct GpuMaterial {
  Float4 ambient;   // rgb
  Float4 diffuse;   // rgb
  Float4 specular;  // rgb, w = shininess k_e
  Float4 mirror;    // rgb
  Float4 transmission;  // rgb, w = index of refraction
  Float4 emission;  // rgb
};

struct GpuSphere {
  Float4 center;  // model point
  float radius;   // geodesic
  uint32_t material;
  uint32_t emitter;  // index into the emitters, or EmitterTable::kNone
  uint32_t padding;
};

struct GpuSphereRef {
  uint32_t sphere;
  uint32_t cell;
};

struct GpuPointLight {
  Float4 position;  // model point
  Float4 intensity;
};

struct GpuTriangle {
  uint32_t material;
  uint32_t smooth;  // 1 when the mesh supplies per-vertex normals (E3)
  uint32_t cell;
  uint32_t emitter;  // index into the emitters, or EmitterTable::kNone
};

struct GpuCell {
  Float16 chart_isometry;  // column-major
  uint32_t face_begin;
  uint32_t face_count;
  uint32_t tube_begin;  // its edge tubes: tubes[tube_begin, tube_begin + tube_count)
  uint32_t tube_count;
  float tube_reach;     // the largest radius among them
  // Its tubes sorted by their first face (GpuCellFace::tubes), then those always tested:
  // tubes[tube_begin + always_begin, tube_begin + tube_count).
  uint32_t always_begin;
  // Its sphere refs, sphere_refs[sphere_begin, sphere_begin + sphere_count) (SPHERE_LIST).
  uint32_t sphere_begin;
  uint32_t sphere_count;
};

// An edge tube's capsule in its cell's chart (scene.h EdgeTube), and two of the cell's faces
// whose planes hold its axis (render/tube_culling.h).
struct GpuTube {
  Float4 a;  // xyz: one end of the axis; w: chart radius
  Float4 b;  // xyz: the other end
  uint32_t material;
  uint32_t face_a, face_b;  // local face indices; kAlwaysTest when no two faces below 32 do
  uint32_t padding;
};

struct GpuCellFace {
  Float4 plane;     // normal, delta
  Float16 pairing;  // column-major
  uint32_t target_cell;
  uint32_t partner;
  uint32_t internal;  // 1: a wall between pieces, not counted as a crossing (INTERNAL_WALLS)
  // The cell's tubes whose first face is this one: local offset | count << 16 (tube_culling.h).
  uint32_t tubes;
};

struct GpuAabb {
  float min[3];
  float max[3];
};

// One cell's share of the acceleration structures: ranges into the flat arrays below.
struct CellGeometry {
  uint32_t first_triangle = 0, triangle_count = 0;
  uint32_t first_sphere_ref = 0, sphere_ref_count = 0;
};

struct PackedScene {
  std::vector<GpuMaterial> materials;
  std::vector<GpuSphere> spheres;
  std::vector<GpuPointLight> lights;
  std::vector<GpuEmitter> emitters;         // the physical model's light sources
  std::vector<GpuLightImage> light_images;  // their images (GpuEmitter ranges)
  double light_cutoff = 0;
  std::vector<GpuCell> cells;
  std::vector<GpuCellFace> faces;
  std::vector<CellGeometry> cell_geometry;  // one per cell
  std::vector<GpuSphereRef> sphere_refs;    // grouped by cell
  std::vector<GpuAabb> sphere_bounds;       // one per sphere ref, in its cell's chart
  std::vector<Float4> positions;            // chart coordinates of triangle vertices, w = 1
  std::vector<Float4> normals;              // one per position (zero when flat)
  std::vector<uint32_t> indices;            // three per triangle, into positions
  std::vector<GpuTriangle> triangles;       // grouped by cell
  std::vector<GpuTube> tubes;               // grouped by cell (GpuCell ranges)
  uint32_t camera_cell = 0;
  Mat4 camera_pose;                         // carried into its cell
};

PackedScene pack_scene(const Scene& scene);

// The chart boxes of the packed triangles from `first` on, which packing orders them by
// (render/spatial_order.h).
std::vector<PrimitiveBox> triangle_boxes(const PackedScene& packed, size_t first = 0);

}  // namespace geodesic
