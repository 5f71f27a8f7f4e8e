// The scene flattened into the arrays the shaders read (std430; the structs are
// shaders/common/gpu_types.h's, which the shaders compile too): model-space spheres, shapes
// and lights, and for every cell of the chart atlas its triangles and edge tubes (in the
// cell's chart) and sphere and shape bounding boxes. Pure data: built and tested without a device.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "common/gpu_types.h"
#include "render/prepare/cells.h"
#include "render/prepare/emitters.h"
#include "render/prepare/spatial_order.h"
#include "scene/scene.h"

namespace geodesic {

using Float4 = std::array<float, 4>;
using Float16 = std::array<float, 16>;

// The GPU-visible structs, defined once with the shaders (shaders/common/gpu_types.h).
using GpuMaterial = gpu::Material;
using GpuSphere = gpu::Sphere;
using GpuSphereRef = gpu::SphereRef;
using GpuShape = gpu::Shape;
using GpuShapeRef = gpu::ShapeRef;
using GpuPointLight = gpu::PointLight;
using GpuTriangle = gpu::TriangleInfo;
using GpuCell = gpu::Cell;
using GpuTube = gpu::Tube;
using GpuCellFace = gpu::CellFace;

struct GpuAabb {
  float min[3];
  float max[3];
};

// One cell's share of the acceleration structures: ranges into the flat arrays below.
struct CellGeometry {
  uint32_t first_triangle = 0, triangle_count = 0;
  uint32_t first_sphere_ref = 0, sphere_ref_count = 0;
  uint32_t first_shape_ref = 0, shape_ref_count = 0;
};

struct PackedScene {
  std::vector<GpuMaterial> materials;
  std::vector<GpuSphere> spheres;
  std::vector<GpuPointLight> lights;
  std::vector<GpuEmitter> emitters;         // the physical model's light sources
  std::vector<GpuLightImage> light_images;  // their images (GpuEmitter ranges)
  double light_cutoff = 0;
  bool every_light_image = true;  // EmitterTable::every_image
  std::vector<GpuCell> cells;
  std::vector<GpuCellFace> faces;
  std::vector<CellGeometry> cell_geometry;  // one per cell
  std::vector<GpuSphereRef> sphere_refs;    // grouped by cell
  std::vector<GpuAabb> sphere_bounds;       // one per sphere ref, in its cell's chart
  std::vector<GpuShape> shapes;             // the analytic shapes (scene/shape.h), model space
  std::vector<GpuShapeRef> shape_refs;      // grouped by cell
  std::vector<GpuAabb> shape_bounds;        // one per shape ref, in its cell's chart
  std::vector<Float4> positions;            // chart coordinates of triangle vertices, w = 1
  std::vector<Float4> normals;              // one per position (zero when flat)
  std::vector<uint32_t> indices;            // three per triangle, into positions
  std::vector<GpuTriangle> triangles;       // grouped by cell
  std::vector<gpu::ListedPrimitive> listed;  // grouped by cell (render/prepare/triangle_list.h)
  std::vector<GpuTube> tubes;               // grouped by cell (GpuCell ranges)
  uint32_t camera_cell = 0;
  Mat4 camera_pose;                         // carried into its cell
};

PackedScene pack_scene(const Scene& scene);

// The chart boxes of the packed triangles from `first` on, which packing orders them by
// (render/prepare/spatial_order.h).
std::vector<PrimitiveBox> triangle_boxes(const PackedScene& packed, size_t first = 0);

}  // namespace geodesic
