// A parallelogram in a chart, the corners a, b = a + u, c = a + u + v and a + v: two triangles
// of a cell's list that make one, (a, b, c) and (a, c, a + v) as the scene's quads and boxes are
// split, tested as one (render/prepare/triangle_list.h). The line meets the plane of
// n = cross(u, v) at s, and the point x (from a) has the coordinates
// alpha = <cross(x, v), n> / |n|^2 and beta = <cross(u, x), n> / |n|^2 along u and v: one test
// where the two watertight triangle tests were two, each dearer.
// Unlike the triangle test it is not watertight by construction: two parallelograms that share
// an edge (the walls of a box) round the point each their own way. So it is closed with a
// margin: alpha in [-m |v| / |n|, 1 + m |v| / |n|] (beta likewise with |u|), m = 2^-18 (32
// float ulps) times 1 + the largest coordinate of the line's origin or of a: neighbours
// overlap by m of the chart, and a float line through an edge they share meets one of them
// (tests/render/parallelogram_probe_test.cpp). shaders/geometry/parallelogram.glsl is the float twin.
#pragma once

#include <optional>

#include "geometry/vec.h"

namespace geodesic {

// Where the chart line o + s d meets the parallelogram of corners a, b, c, s in
// (s_min, s_max], two-sided, with the point's alpha and beta.
struct ChartParallelogramHit {
  double s = 0;
  double alpha = 0;
  double beta = 0;
};
std::optional<ChartParallelogramHit> intersect_chart_parallelogram(const Vec3& o, const Vec3& d,
                                                                   const Vec3& a, const Vec3& b,
                                                                   const Vec3& c, double s_min,
                                                                   double s_max);

// The hit as the triangle of the pair that holds it reports it (Vulkan's barycentrics): the
// first, (a, b, c), where beta <= alpha, at (alpha - beta, beta); else the second,
// (a, c, a + v), at (alpha, beta - alpha).
struct PairedTriangleHit {
  int half = 0;  // 0 the first triangle, 1 the second
  double u = 0;
  double v = 0;
};
PairedTriangleHit paired_triangle_hit(double alpha, double beta);

}  // namespace geodesic
