// The watertight triangle test in float GLSL (shaders/geometry/triangle.glsl, through the
// geometry probe), which cells of a few triangles use instead of a traversal (TRIANGLE_LIST),
// against its double twin (model::intersect_chart_triangle): lines at the inside, past an edge,
// at grazing angles and a thousand units from the origin must hit or miss as the twin says
// outside a band of 1e-4 of the triangle's size round its edges, at the twin's s and
// barycentrics; and lines through an edge or a vertex that triangles share, in float, must meet
// at least one of them (no light through the seams of a closed box).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "geometry_probe.h"

namespace geodesic::test {
namespace {

using model::intersect_chart_triangle;

struct Triangle {
  Vec3 a, b, c;
};

void store(ProbeCase& c, const Triangle& t, const Vec3& o, const Vec3& d, double s_max) {
  c.triangle_a = f4(t.a, s_max);
  c.triangle_b = f4(t.b, 0);
  c.triangle_c = f4(t.c, 0);
  c.chart = f4(o, 0);
  c.normal = f4(d, 0);
}

// The case as the probe sees it: every input rounded to float.
struct Seen {
  Triangle t;
  Vec3 o, d;
  double s_max;
};
Seen read_triangle_case(const ProbeCase& c) {
  return {{v3(c.triangle_a), v3(c.triangle_b), v3(c.triangle_c)}, v3(c.chart), v3(c.normal),
          c.triangle_a[3]};
}

Vec3 at(const Triangle& t, double u, double v) { return (1 - u - v) * t.a + u * t.b + v * t.c; }

// The line's signed barycentrics on the triangle's plane, the smallest of them scaled by the
// triangle's size: how far inside (> 0) or outside the line passes.
double margin(const Seen& s) {
  const Vec3 e1 = s.t.b - s.t.a, e2 = s.t.c - s.t.a, n = cross(e1, e2);
  const double denom = dot(s.d, n);
  if (denom == 0) return -1;
  const Vec3 x = s.o + (dot(s.t.a - s.o, n) / denom) * s.d;
  const double area2 = dot(n, n);
  const double u = dot(cross(x - s.t.a, e2), n) / area2, v = dot(cross(e1, x - s.t.a), n) / area2;
  return std::min({u, v, 1 - u - v});
}

TEST(TriangleProbe, FloatIntersectionMatchesTheDoubleTwin) {
  ProbeCaseMaker maker(GeometryKind::Euclidean, 4111);  // the triangle lives in a chart
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 8000; ++i) {
    ProbeCase c = maker.make();
    // Every fourth case a thousand units out, as a chart of a large flat scene can be.
    const Vec3 shift = i % 4 == 3 ? sample.uniform(100, 1000) * sample.unit3() : Vec3{};
    const double size = sample.uniform(0.05, 2);
    const Triangle t{shift + size * sample.ball(1), shift + size * sample.ball(1),
                     shift + size * sample.ball(1)};
    const Vec3 n = normalize(cross(t.b - t.a, t.c - t.a));
    double u = sample.uniform(0, 1), v = sample.uniform(0, 1);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    if (i % 4 == 1) {  // past an edge, by up to half the triangle
      const double out = -sample.uniform(0.001, 0.5);
      const int edge = i / 4 % 3;
      if (edge == 0) u = out;
      else if (edge == 1) v = out;
      else u = 1 - v - out;
    }
    const Vec3 target = at(t, u, v);
    const AimedLine line = line_at(sample, target, n, size, i);
    store(c, t, line.o, line.d, line.s_max);
    cases.push_back(c);
  }
  const auto results = run_probe(GeometryKind::Euclidean, cases);
  std::vector<TwinCase> compared;
  for (size_t i = 0; i < cases.size(); ++i) {
    const Seen s = read_triangle_case(cases[i]);
    const auto twin = intersect_chart_triangle(s.o, s.d, s.t.a, s.t.b, s.t.c, 0, s.s_max);
    const Vec3 n = normalize(cross(s.t.b - s.t.a, s.t.c - s.t.a));
    compared.push_back({twin ? std::optional(std::array{twin->s, twin->u, twin->v}) : std::nullopt,
                        results[i].triangle, margin(s), std::abs(dot(normalize(s.d), n)),
                        length(s.o)});
  }
  expect_twin_agrees(compared, "triangle", "barycentrics");
}

// Quads split along a diagonal and fans of triangles round a vertex, the lines aimed at float
// points of the diagonal and at the vertex itself, near and far from the origin, head-on and
// grazing: each line must meet at least one of the triangles, as a closed surface needs.
TEST(TriangleProbe, LinesThroughSharedEdgesAndVerticesMeetATriangle) {
  ProbeCaseMaker maker(GeometryKind::Euclidean, 4127);
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  std::vector<SeamLine> lines;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 shift = i % 3 == 2 ? sample.uniform(100, 1000) * sample.unit3() : Vec3{};
    const double size = sample.uniform(0.05, 2);
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
    lines.push_back({cases.size(), triangles.size()});
    for (const Triangle& t : triangles) {
      ProbeCase c = maker.make();
      store(c, t, o, d, kFar);
      cases.push_back(c);
    }
  }
  expect_every_line_meets_a_piece(run_probe(GeometryKind::Euclidean, cases), lines,
                                  &ProbeResult::triangle, "shared edges and vertices");
}

}  // namespace
}  // namespace geodesic::test
