// What the segments of a cell test one by one where the pipeline lists its triangles
// (PipelineFeatures::triangle_list, shaders/primitives/triangle_list.glsl): each of the cell's
// triangles, except that two which make a parallelogram, (a, b, c) and (a, c, d) with
// d = a + c - b as scene_loader splits quads and boxes, are one primitive tested as the
// parallelogram (geometry/parallelogram.h): the Cornell box's 16 triangles are 8 tests. A
// cell's pairs come first, then its lone triangles. Cells of more than kTriangleListLength
// triangles list none (the pipeline traverses them).
//
// Shadow segments skip the primitives on the hull of the scene (list_hull_first): in a
// Euclidean scene that is not a quotient (one cell without faces) and holds no analytic shapes,
// a listed primitive whose plane has everything the scene holds on one side (every triangle
// corner, every sphere, every point light) lies on the boundary of their convex hull. A segment
// between two points of that hull meets such a plane only at its ends, or lies in it (then the
// light lies in the plane and its cosine at the surface is 0), so no shadow segment from a
// surface to a light can cross the primitive. The shadow segment starts off the surface by its
// offset, which takes it past a hull plane only from a surface on that plane facing out (no
// light is in front of it: it sends no shadow segment) or from a sphere's point of contact with
// the plane, where the plane could only report the self-intersection the offset is there to
// avoid. The Cornell box's floor and three walls are on its hull; its ceiling is not, the light
// being above it.
#pragma once

#include <cstdint>
#include <vector>

#include "common/gpu_types.h"

namespace geodesic {

struct Cell;
struct PackedScene;
using GpuListedPrimitive = gpu::ListedPrimitive;
using GpuCell = gpu::Cell;
constexpr uint32_t kUnpaired = ~0u;  // ListedPrimitive::second of a lone triangle

// The primitives of the packed triangles [first, first + count), appended to packed.listed
// (the pairs first); returns how many are pairs.
uint32_t list_cell_triangles(uint32_t first, uint32_t count, PackedScene& packed);

// Orders the cell's listed primitives so that those on the scene's hull come first among its
// pairs and first among its lone triangles, and sets cell.listed_hull_pairs and
// cell.listed_hull_lone to their numbers (both 0 where the conditions above do not hold).
// `packed` holds the scene's spheres and lights and the cell's triangles
// [first_triangle, first_triangle + triangle_count) and listed primitives.
void list_hull_first(bool euclidean, const Cell& chart, uint32_t first_triangle,
                     uint32_t triangle_count, bool holds_shapes, PackedScene& packed,
                     GpuCell& cell);

}  // namespace geodesic
