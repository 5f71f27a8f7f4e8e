// The watertight triangle test in float GLSL (shaders/geometry/triangle.glsl, through the
// geometry probe), which cells of a few triangles use instead of a traversal (TRIANGLE_LIST),
// against its double twin (model::intersect_chart_triangle): lines at the inside, past an edge,
// at grazing angles and a thousand units from the origin must hit or miss as the twin says
// outside a band of 1e-4 of the triangle's size round its edges, at the twin's s and
// barycentrics; and lines through an edge or a vertex that triangles share, in float, must meet
// at least one of them (no light through the seams of a closed box).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "flat_piece_probe.h"

namespace geodesic::test {
namespace {

using model::intersect_chart_triangle;
using Triangle = Corners;

Vec3 at(const Triangle& t, double u, double v) { return (1 - u - v) * t.a + u * t.b + v * t.c; }

// The line's signed barycentrics on the triangle's plane, the smallest of them scaled by the
// triangle's size: how far inside (> 0) or outside the line passes.
double margin(const CornerCase& k) {
  const Triangle& t = k.piece;
  const Vec3 e1 = t.b - t.a, e2 = t.c - t.a, n = cross(e1, e2);
  const double denom = dot(k.d, n);
  if (denom == 0) return -1;
  const Vec3 x = k.o + (dot(t.a - k.o, n) / denom) * k.d;
  const double area2 = dot(n, n);
  const double u = dot(cross(x - t.a, e2), n) / area2, v = dot(cross(e1, x - t.a), n) / area2;
  return std::min({u, v, 1 - u - v});
}

TEST(TriangleProbe, FloatIntersectionMatchesTheDoubleTwin) {
  const auto aim = [](ModelSampler& sample, int i, const Vec3& shift, double size) {
    const Triangle t{shift + size * sample.ball(1), shift + size * sample.ball(1),
                     shift + size * sample.ball(1)};
    double u = sample.uniform(0, 1), v = sample.uniform(0, 1);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    if (i % 4 == 1) {  // past an edge, by up to half the triangle
      const double out = -sample.uniform(0.001, 0.5);
      const int edge = i / 4 % 3;
      if (edge == 0) u = out;
      else if (edge == 1) v = out;
      else u = 1 - v - out;
    }
    return AimedPiece{t, at(t, u, v)};
  };
  const auto twin = [](const CornerCase& k) -> std::optional<std::array<double, 3>> {
    const Triangle& t = k.piece;
    const auto hit = intersect_chart_triangle(k.o, k.d, t.a, t.b, t.c, 0, k.s_max);
    if (!hit) return std::nullopt;
    return std::array{hit->s, hit->u, hit->v};
  };
  expect_pieces_agree_with_twin(4111, aim, &ProbeResult::triangle, twin, margin, "triangle",
                                "barycentrics");
}

// Quads split along a diagonal and fans of triangles round a vertex, the lines aimed at float
// points of the diagonal and at the vertex itself, near and far from the origin, head-on and
// grazing: each line must meet at least one of the triangles, as a closed surface needs.
TEST(TriangleProbe, LinesThroughSharedEdgesAndVerticesMeetATriangle) {
  const auto seam = [](ModelSampler& sample, int i, const Vec3& shift, double size) {
    const Vec3 centre = shift + size * sample.ball(1);
    const Vec3 n = sample.unit3();
    const Vec3 e1 = normalize(cross(n, sample.unit3())), e2 = cross(n, e1);
    std::vector<Triangle> triangles;
    Vec3 target;
    if (i % 2 == 0) {  // a quad a b c d split along a c; aimed at a float point of a c
      const Vec3 a = centre - size * e1, b = centre - size * e2, c = centre + size * e1,
                 d = centre + size * e2;
      triangles = {{a, b, c}, {a, c, d}};
      const double f = sample.uniform(0.01, 0.99);
      target = v3(f4(a + f * (c - a), 0));
    } else {  // a fan of five round the vertex `centre`, aimed at it
      for (int k = 0; k < 5; ++k) {
        const double a0 = 2 * std::numbers::pi * k / 5, a1 = 2 * std::numbers::pi * (k + 1) / 5;
        triangles.push_back({centre, centre + size * (std::cos(a0) * e1 + std::sin(a0) * e2),
                             centre + size * (std::cos(a1) * e1 + std::sin(a1) * e2)});
      }
      target = v3(f4(centre, 0));
    }
    Vec3 d = sample.unit3();
    if (i % 4 == 1) d = normalize(d - dot(d, n) * n + std::tan(sample.uniform(0.01, 0.1)) * n);
    if (std::abs(dot(d, n)) < 1e-3) d = n;
    const Vec3 o = target - sample.uniform(0.1, 3) * (1 + size) * d;
    return SeamLine{triangles, o, d};
  };
  expect_every_seam_line_meets_a_piece(4127, seam, &ProbeResult::triangle,
                                       "shared edges and vertices");
}

}  // namespace
}  // namespace geodesic::test
