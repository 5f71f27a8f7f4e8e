// What the segments of a cell test one by one where the pipeline lists its triangles
// (PipelineFeatures::triangle_list, shaders/primitives/triangle_list.glsl): each of the cell's
// triangles, except that two which make a parallelogram, (a, b, c) and (a, c, d) with
// d = a + c - b as scene_loader splits quads and boxes, are one primitive tested as the
// parallelogram (geometry/parallelogram.h): the Cornell box's 16 triangles are 8 tests. A
// cell's pairs come first, then its lone triangles. Cells of more than kTriangleListLength
// triangles list none (the pipeline traverses them).
#pragma once

#include <cstdint>
#include <vector>

#include "common/gpu_types.h"

namespace geodesic {

struct PackedScene;
using GpuListedPrimitive = gpu::ListedPrimitive;
constexpr uint32_t kUnpaired = ~0u;  // ListedPrimitive::second of a lone triangle

// The primitives of the packed triangles [first, first + count), appended to packed.listed
// (the pairs first); returns how many are pairs.
uint32_t list_cell_triangles(uint32_t first, uint32_t count, PackedScene& packed);

}  // namespace geodesic
