// The parallelogram test in float GLSL (shaders/geometry/parallelogram.glsl, through the geometry
// probe), which cells that list their triangles use for two that make a parallelogram
// (TRIANGLE_LIST), against its double twin (intersect_chart_parallelogram): lines at the inside,
// past an edge, at grazing angles and a thousand units from the origin must hit or miss as the
// twin says outside a band of 1e-4 of the size round its edges, at the twin's s, alpha and beta;
// and lines through an edge or a corner that parallelograms share (a box's walls and corners,
// coplanar tiles), in float, must meet at least one of them: the margin closes the seams that
// the watertight triangle test closes by construction.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/model.h"
#include "geometry/parallelogram.h"
#include "flat_piece_probe.h"

namespace geodesic::test {
namespace {

using Parallelogram = Corners;  // corners a, a + u, a + u + v (and a + v)

// How far inside (> 0) or outside the line passes, in units of the sides: the smallest of
// alpha, 1 - alpha, beta, 1 - beta on the plane.
double margin(const CornerCase& k) {
  const Vec3 a = k.piece.a, u = k.piece.b - a, v = k.piece.c - k.piece.b, n = cross(u, v);
  const double denom = dot(n, k.d);
  if (denom == 0) return -1;
  const Vec3 x = k.o + (dot(n, a - k.o) / denom) * k.d - a;
  const double alpha = dot(cross(x, v), n) / dot(n, n), beta = dot(cross(u, x), n) / dot(n, n);
  return std::min({alpha, 1 - alpha, beta, 1 - beta});
}

TEST(ParallelogramProbe, FloatIntersectionMatchesTheDoubleTwin) {
  const auto aim = [](ModelSampler& sample, int i, const Vec3& shift, double size) {
    // Sides of 0.2 to 1 of the size, at 12 degrees or more to each other (no slivers, whose
    // alpha or beta a float ulp of the chart moves by much).
    const Vec3 a = shift + size * sample.ball(1);
    Vec3 u, v;
    do {
      u = size * sample.uniform(0.2, 1) * sample.unit3();
      v = size * sample.uniform(0.2, 1) * sample.unit3();
    } while (length(cross(u, v)) < 0.2 * length(u) * length(v));
    double alpha = sample.uniform(0, 1), beta = sample.uniform(0, 1);
    if (i % 4 == 1) {  // past an edge, by up to half the side
      const double out = sample.uniform(0.001, 0.5);
      if (i / 4 % 2 == 0) alpha = i / 8 % 2 ? -out : 1 + out;
      else beta = i / 8 % 2 ? -out : 1 + out;
    }
    return AimedPiece{{a, a + u, a + u + v}, a + alpha * u + beta * v};
  };
  const auto twin = [](const CornerCase& k) -> std::optional<std::array<double, 3>> {
    const Parallelogram& p = k.piece;
    const auto hit = intersect_chart_parallelogram(k.o, k.d, p.a, p.b, p.c, 0, k.s_max);
    if (!hit) return std::nullopt;
    return std::array{hit->s, hit->alpha, hit->beta};
  };
  expect_pieces_agree_with_twin(4133, aim, &ProbeResult::parallelogram, twin, margin,
                                "parallelogram", "alpha and beta");
}

// Two walls of a box meeting at an edge (at a right angle, or folded 10 to 170 degrees), two
// coplanar tiles side by side, and the three walls round a box's corner; the lines aimed at float
// points of the shared edge or at the corner, near and far from the origin, head-on and grazing:
// each must meet at least one parallelogram.
TEST(ParallelogramProbe, LinesThroughSharedEdgesAndCornersMeetAParallelogram) {
  const auto seam = [](ModelSampler& sample, int i, const Vec3& shift, double size) {
    const Vec3 e = shift + size * sample.ball(1);  // a shared corner
    const Vec3 x = normalize(sample.unit3()), y0 = normalize(cross(x, sample.unit3()));
    const Vec3 z0 = cross(x, y0);
    std::vector<Parallelogram> walls;
    Vec3 target;
    const int kind = i % 3;
    if (kind == 0) {  // two walls folded along the edge e + t x
      const double angle = i % 2 ? 0.5 * std::numbers::pi : sample.uniform(0.17, 2.97);
      const Vec3 y1 = std::cos(angle) * y0 + std::sin(angle) * z0;
      walls = {{e, e + size * x, e + size * x + size * y0},
               {e + size * x, e, e + size * y1}};  // (a, a + u, a + u + v) with u = -x
      target = v3(f4(e + sample.uniform(0.01, 0.99) * size * x, 0));
    } else if (kind == 1) {  // coplanar tiles on either side of the edge
      walls = {{e, e + size * x, e + size * x + size * y0},
               {e + size * x, e, e - size * y0}};
      target = v3(f4(e + sample.uniform(0.01, 0.99) * size * x, 0));
    } else {  // a box's corner: three walls round e
      walls = {{e, e + size * x, e + size * x + size * y0},
               {e, e + size * y0, e + size * y0 + size * z0},
               {e, e + size * z0, e + size * z0 + size * x}};
      target = v3(f4(e, 0));
    }
    Vec3 d = sample.unit3();
    if (i % 4 == 1) d = normalize(d + std::tan(sample.uniform(0.01, 0.1)) * normalize(x));
    const Vec3 o = target - sample.uniform(0.1, 3) * (1 + size) * d;
    return SeamLine{walls, o, d};
  };
  expect_every_seam_line_meets_a_piece(4139, seam, &ProbeResult::parallelogram,
                                       "shared edges and corners");
}

// The twin against the double triangle test on the two halves: where the parallelogram is met
// away from its edges, the half paired_triangle_hit names is met at the same s, with the same
// barycentrics, and the other half is not.
TEST(ParallelogramProbe, TheHalfItNamesIsTheTriangleTheLineMeets) {
  ModelSampler sample(GeometryKind::Euclidean, 4153);
  int checked = 0;
  for (int i = 0; i < 4000; ++i) {
    const double size = sample.uniform(0.05, 2);
    const Vec3 a = size * sample.ball(1), u = size * sample.ball(1), v = size * sample.ball(1);
    const Vec3 b = a + u, c = a + u + v, d4 = a + v;
    const Vec3 target = a + sample.uniform(0.01, 0.99) * u + sample.uniform(0.01, 0.99) * v;
    const Vec3 d = sample.unit3(), o = target - sample.uniform(0.1, 3) * d;
    const auto hit = intersect_chart_parallelogram(o, d, a, b, c, 0, kFar);
    if (std::abs(dot(normalize(cross(u, v)), d)) < 0.05) continue;  // too grazing to compare
    ASSERT_TRUE(hit) << "case " << i;
    const PairedTriangleHit half = paired_triangle_hit(hit->alpha, hit->beta);
    if (std::abs(hit->alpha - hit->beta) < 1e-6) continue;  // on the diagonal: either
    const auto first = model::intersect_chart_triangle(o, d, a, b, c, 0, kFar);
    const auto second = model::intersect_chart_triangle(o, d, a, c, d4, 0, kFar);
    const auto& met = half.half == 0 ? first : second;
    ASSERT_TRUE(met) << "case " << i;
    EXPECT_FALSE(half.half == 0 ? second : first) << "case " << i;
    EXPECT_NEAR(met->s, hit->s, 1e-9 * (1 + hit->s));
    EXPECT_NEAR(met->u, half.u, 1e-9);
    EXPECT_NEAR(met->v, half.v, 1e-9);
    ++checked;
  }
  EXPECT_GT(checked, 3000);
}

}  // namespace
}  // namespace geodesic::test
