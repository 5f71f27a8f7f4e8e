// The flat pieces' probe tests (the float triangle and parallelogram tests of chart cells that
// list their triangles) seen from C++: a piece's three corners and a line in a probe case, the
// comparison of the float test with its double twin, and lines through the seams that pieces
// share, each of which must meet one of them.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "geometry_probe.h"

namespace geodesic::test {

// A line through `target` on a surface of unit normal n and size `size`, for case i of a twin
// comparison: in a random direction, or (i % 4 == 2) grazing the surface by 0.5 to 6 degrees
// from either side; starting 0.1 to 3 (1 + size) before it, and every sixteenth (i % 16 == 4)
// cut off halfway there by sMax.
struct AimedLine {
  Vec3 o, d;
  double s_max;
};
inline AimedLine line_at(ModelSampler& sample, const Vec3& target, const Vec3& n, double size,
                         int i) {
  Vec3 d = sample.unit3();
  if (i % 4 == 2) {
    const Vec3 along = normalize(d - dot(d, n) * n);
    d = normalize(along + std::tan(sample.uniform(0.01, 0.1)) * (i % 8 < 4 ? n : -n));
  }
  const double back = sample.uniform(0.1, 3) * (1 + size);
  return {target - back * d, d, i % 16 == 4 ? 0.5 * back : kFar};
}

// A float chart test against its double twin, case by case: where the line passes within 1e-4
// (in the surface's own coordinates) of an edge, either may round either way (the band, not
// compared); elsewhere both hit or both miss, a hit at the same s to 1e-5 (|o| + s + 1) / cos
// and at the same two surface coordinates to 1e-3 / cos (cos: the line's to the surface).
struct TwinCase {
  std::optional<std::array<double, 3>> twin;  // s and the two coordinates, or no hit
  F4 found;            // the float test's: s (>= 1e29: none) and the two coordinates
  double inside;       // how far inside the line passes, in the coordinates' units (< 0 out)
  double cosine;
  double origin_size;  // |o|
};
inline void expect_twin_agrees(const std::vector<TwinCase>& cases, const char* what,
                               const char* coordinates) {
  int hits = 0, misses = 0, band = 0, cut = 0;
  double worst_s = 0, worst_coordinates = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const TwinCase& c = cases[i];
    const F4& g = c.found;
    if (std::abs(c.inside) < 1e-4) {
      ++band;
      continue;
    }
    if (!c.twin) {
      ++misses;
      cut += c.inside > 0;  // inside, but past sMax
      EXPECT_GE(g[0], 1e29f) << "case " << i << ": float hit at " << g[0];
      continue;
    }
    ++hits;
    const auto& [s, x, y] = *c.twin;
    ASSERT_LT(g[0], 1e29f) << "case " << i << ": float miss, double hit at " << s;
    const double error = std::abs(g[0] - s) * c.cosine / (c.origin_size + s + 1);
    worst_s = std::max(worst_s, error);
    EXPECT_LE(error, 1e-5) << "case " << i << ": float " << g[0] << ", double " << s;
    const double off = std::max(std::abs(g[1] - x), std::abs(g[2] - y)) * c.cosine;
    worst_coordinates = std::max(worst_coordinates, off);
    EXPECT_LE(off, 1e-3) << "case " << i;
  }
  std::printf("%s: %d hits, %d misses (%d inside but past sMax), %d in the edge band; worst s "
              "error %.2e (|o| + s + 1) / cos, %s %.2e / cos\n",
              what, hits, misses, cut, band, worst_s, coordinates, worst_coordinates);
  EXPECT_GT(hits, 5000);
  EXPECT_GT(misses, 2300);
  EXPECT_GT(cut, 400);
  EXPECT_LT(band, 200);
}

// A flat piece given by three corners (a triangle; a parallelogram's a, a + u, a + u + v) and a
// line o + s d up to sMax, in the case's triangle, chart and normal fields. Read back, every
// input is rounded to float: the case as the probe sees it.
struct Corners {
  Vec3 a, b, c;
};
struct CornerCase {
  Corners piece;
  Vec3 o, d;
  double s_max;
};
inline void store_corners(ProbeCase& c, const CornerCase& k) {
  c.triangle_a = f4(k.piece.a, k.s_max);
  c.triangle_b = f4(k.piece.b, 0);
  c.triangle_c = f4(k.piece.c, 0);
  c.chart = f4(k.o, 0);
  c.normal = f4(k.d, 0);
}
inline CornerCase read_corners(const ProbeCase& c) {
  return {{v3(c.triangle_a), v3(c.triangle_b), v3(c.triangle_c)}, v3(c.chart), v3(c.normal),
          c.triangle_a[3]};
}

// A piece and the point on its plane a line is aimed at (inside it, or past an edge).
struct AimedPiece {
  Corners piece;
  Vec3 target;
};

// A float flat-piece test (the probe's results in `field`) against its double twin on 8000
// lines: pieces of size 0.05 to 2, every fourth 100 to 1000 units from the origin, as a chart of
// a large flat scene can be; aim(sample, i, shift, size) makes case i's piece and target, and
// line_at its line. twin(k) gives s and the piece's two coordinates (or none), inside(k) how far
// inside the piece the line passes.
template <typename Aim, typename Twin, typename Inside>
void expect_pieces_agree_with_twin(uint64_t seed, Aim aim, F4 ProbeResult::*field, Twin twin,
                                   Inside inside, const char* what, const char* coordinates) {
  ProbeCaseMaker maker(GeometryKind::Euclidean, seed);
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  for (int i = 0; i < 8000; ++i) {
    ProbeCase c = maker.make();
    const Vec3 shift = i % 4 == 3 ? sample.uniform(100, 1000) * sample.unit3() : Vec3{};
    const double size = sample.uniform(0.05, 2);
    const AimedPiece p = aim(sample, i, shift, size);
    const Corners& q = p.piece;
    const AimedLine line =
        line_at(sample, p.target, normalize(cross(q.b - q.a, q.c - q.a)), size, i);
    store_corners(c, {q, line.o, line.d, line.s_max});
    cases.push_back(c);
  }
  const std::vector<ProbeResult> results = run_probe(GeometryKind::Euclidean, cases);
  std::vector<TwinCase> compared;
  for (size_t i = 0; i < cases.size(); ++i) {
    const CornerCase k = read_corners(cases[i]);
    const Vec3 n = normalize(cross(k.piece.b - k.piece.a, k.piece.c - k.piece.a));
    compared.push_back({twin(k), results[i].*field, inside(k), std::abs(dot(normalize(k.d), n)),
                        length(k.o)});
  }
  expect_twin_agrees(compared, what, coordinates);
}

// Lines through an edge or a vertex that pieces of a surface share (triangles, parallelograms),
// 3000 of them: pieces of size 0.05 to 2, every third 100 to 1000 units from the origin.
// seam(sample, i, shift, size) makes line i and its pieces; each line must meet at least one of
// them (the probe's `field`, s < kFar), as a closed surface needs. Prints the counts under `what`.
struct SeamLine {
  std::vector<Corners> pieces;
  Vec3 o, d;
};
template <typename Seam>
void expect_every_seam_line_meets_a_piece(uint64_t seed, Seam seam, F4 ProbeResult::*field,
                                          const char* what) {
  ProbeCaseMaker maker(GeometryKind::Euclidean, seed);
  ModelSampler& sample = maker.sample();
  std::vector<ProbeCase> cases;
  std::vector<size_t> first;  // line l's cases, one per piece: [first[l], first[l + 1])
  for (int i = 0; i < 3000; ++i) {
    const Vec3 shift = i % 3 == 2 ? sample.uniform(100, 1000) * sample.unit3() : Vec3{};
    const double size = sample.uniform(0.05, 2);
    const SeamLine line = seam(sample, i, shift, size);
    first.push_back(cases.size());
    for (const Corners& piece : line.pieces) {
      ProbeCase c = maker.make();
      store_corners(c, {piece, line.o, line.d, kFar});
      cases.push_back(c);
    }
  }
  first.push_back(cases.size());
  const std::vector<ProbeResult> results = run_probe(GeometryKind::Euclidean, cases);
  int holes = 0, double_hits = 0;
  for (size_t l = 0; l + 1 < first.size(); ++l) {
    int met = 0;
    for (size_t k = first[l]; k < first[l + 1]; ++k) met += (results[k].*field)[0] < 1e29f;
    holes += met == 0;
    double_hits += met > 1;
    EXPECT_GT(met, 0) << "line " << l << " passes between its pieces";
  }
  std::printf("%s: %zu lines, %d through none, %d meeting two or more\n", what,
              first.size() - 1, holes, double_hits);
}

}  // namespace geodesic::test
