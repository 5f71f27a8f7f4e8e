#include "scene/atlas_piece.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "scene/scene.h"

namespace geodesic {
namespace {

constexpr auto kS3 = GeometryKind::Spherical;
constexpr double kPi = std::numbers::pi;
// One cell per piece; L(p, 1) needs p of them (the scene format allows p <= 1000).
constexpr std::size_t kMaxLunePieces = 1024;

using Mat2 = std::array<std::array<double, 2>, 2>;

// An orthonormal basis of the span of `vectors` (Gram-Schmidt), at most `limit` long.
std::vector<Vec4> span_basis(const std::vector<Vec4>& vectors, std::size_t limit) {
  std::vector<Vec4> basis;
  for (Vec4 v : vectors) {
    for (const Vec4& b : basis) v = v - dot(v, b) * b;
    const double n = std::sqrt(dot(v, v));
    if (n > 1e-9) basis.push_back(v / n);
    if (basis.size() == limit) break;
  }
  return basis;
}

Vec4 on_circle(const Vec4& a, const Vec4& b, double angle) {
  return std::cos(angle) * a + std::sin(angle) * b;
}

[[noreturn]] void too_many() {
  throw SceneError("generators: the domain needs more than " + std::to_string(kMaxLunePieces) +
                   " chart pieces (a lune its pairings twist by a small angle), and the renderer "
                   "keeps at most " + std::to_string(kMaxLunePieces) + " cells");
}

// The angles around C, as many as the pairings' action on C needs: the orbits of generic
// angles under the group that action generates, added until no gap exceeds pi / 2 (so that
// each piece lies within pi / 3 of its centre).
std::vector<double> fan_angles(const std::vector<Mat2>& actions) {
  std::vector<Mat2> group{{{{1, 0}, {0, 1}}}};
  for (std::size_t i = 0; i < group.size() && group.size() <= kMaxLunePieces; ++i)
    for (const Mat2& a : actions) {
      Mat2 m{};
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) m[r][c] = a[r][0] * group[i][0][c] + a[r][1] * group[i][1][c];
      const bool known = std::any_of(group.begin(), group.end(), [&](const Mat2& g) {
        return std::abs(g[0][0] - m[0][0]) + std::abs(g[0][1] - m[0][1]) +
                   std::abs(g[1][0] - m[1][0]) + std::abs(g[1][1] - m[1][1]) < 1e-9;
      });
      if (!known) group.push_back(m);
    }
  if (group.size() > kMaxLunePieces) too_many();
  std::vector<double> angles;
  double seed = 0.2718;
  for (;;) {
    for (const Mat2& g : group) {
      const double x = std::cos(seed), y = std::sin(seed);
      double a = std::atan2(g[1][0] * x + g[1][1] * y, g[0][0] * x + g[0][1] * y);
      if (a < 0) a += 2 * kPi;
      if (std::none_of(angles.begin(), angles.end(), [&](double b) { return std::abs(a - b) < 1e-9; }))
        angles.push_back(a);
    }
    std::sort(angles.begin(), angles.end());
    if (angles.size() > kMaxLunePieces) too_many();
    double widest = 0;
    for (std::size_t i = 0; i < angles.size(); ++i) {
      const double next = i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * kPi;
      if (next - angles[i] > widest) widest = next - angles[i], seed = angles[i] + (next - angles[i]) / 2;
    }
    if (angles.size() >= 3 && widest <= kPi / 2 + 1e-9) return angles;
  }
}

}  // namespace

std::optional<std::vector<AtlasPiece>> lune_pieces(const std::vector<GroupElement>& elements,
                                                   double tolerance) {
  std::vector<Vec4> normals;  // of the bisectors, element i at i - 1
  for (std::size_t i = 1; i < elements.size(); ++i) normals.push_back(elements[i].point - model::origin());
  if (span_basis(normals, 3).size() != 2) return std::nullopt;
  const std::vector<Vec4> pi = span_basis(normals, 2);

  // The wedge of Pi that D projects into: its edges are perpendicular to the normals of the two
  // elements whose bisectors bound D.
  struct Edge {
    Vec4 direction;
    int element;
  };
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const double a = dot(normals[i], pi[0]), b = dot(normals[i], pi[1]);
    for (const double sign : {1.0, -1.0}) {
      const Vec4 d = sign / std::hypot(a, b) * (-b * pi[0] + a * pi[1]);
      const bool inside = std::all_of(normals.begin(), normals.end(), [&](const Vec4& m) {
        return dot(d, m) <= 1e-9 * std::sqrt(dot(m, m));
      });
      const bool known = std::any_of(edges.begin(), edges.end(), [&](const Edge& e) {
        return dot(e.direction, d) > 1 - 1e-12;
      });
      if (inside && !known) edges.push_back({d, int(i) + 1});
    }
  }
  if (edges.size() != 2 || dot(edges[0].direction, edges[1].direction) < -1 + 1e-9) return std::nullopt;
  // Pi's circle from one edge (angle 0) to the other (angle `arc` < pi), and C's plane.
  const Vec4 e1 = edges[0].direction;
  const Vec4 e2 = span_basis({e1, edges[1].direction}, 2)[1];
  const double arc = std::acos(std::clamp(dot(e1, edges[1].direction), -1.0, 1.0));
  std::vector<Vec4> axes = {e1, e2};
  for (int i = 0; i < 4; ++i) axes.push_back(Vec4{double(i == 0), double(i == 1), double(i == 2), double(i == 3)});
  const std::vector<Vec4> frame4 = span_basis(axes, 4);
  const Vec4 u1 = frame4[2], u2 = frame4[3];

  // How the face pairings turn (or reflect) C: they preserve it, as its points are the edge of
  // every face.
  std::vector<Mat2> actions;
  for (const Edge& e : edges) {
    const Mat4& g = elements[e.element].g;
    actions.push_back({{{dot(u1, g * u1), dot(u1, g * u2)}, {dot(u2, g * u1), dot(u2, g * u2)}}});
  }
  const std::vector<double> fan = fan_angles(actions);
  const int n = static_cast<int>(fan.size());
  const int slices = arc > kPi / 2 ? 2 : 1;  // across the arc, so that no piece reaches pi / 3
  if (std::size_t(n * slices) > kMaxLunePieces) too_many();

  auto fan_point = [&](int j) { return on_circle(u1, u2, fan[j % n] + (j >= n ? 2 * kPi : 0)); };
  // The half-space on the side of increasing angle of the half sphere at `angle` in plane (a, b).
  auto beyond = [](const Vec4& a, const Vec4& b, double angle) {
    return std::sin(angle) * a - std::cos(angle) * b;  // <x, m> <= 0 <=> sin(angle_x - angle) >= 0
  };
  std::vector<AtlasPiece> pieces;
  for (int j = 0; j < n; ++j)
    for (int s = 0; s < slices; ++s) {
      const int index = j * slices + s;
      const double from = arc * s / slices, to = arc * (s + 1) / slices;
      const Vec4 centre = model::normalize_point(
          kS3, model::normalize_point(kS3, fan_point(j) + fan_point(j + 1)) +
                   on_circle(e1, e2, (from + to) / 2));
      AtlasPiece piece{index, model::translation_from(kS3, centre), {}, {}};
      const double a0 = fan[j], a1 = j + 1 < n ? fan[j + 1] : fan[0] + 2 * kPi;
      const std::array<std::pair<Vec4, AtlasWall>, 4> walls = {{
          {beyond(u1, u2, a0), {{}, true, ((j + n - 1) % n) * slices + s}},
          {-beyond(u1, u2, a1), {{}, true, ((j + 1) % n) * slices + s}},
          {s == 0 ? normals[edges[0].element - 1] : beyond(e1, e2, from),
           {{}, s != 0, s == 0 ? edges[0].element : index - 1}},
          {s + 1 == slices ? normals[edges[1].element - 1] : -beyond(e1, e2, to),
           {{}, s + 1 != slices, s + 1 == slices ? edges[1].element : index + 1}},
      }};
      std::vector<ChartPlane> planes;
      for (const auto& [m, wall] : walls) {
        const auto plane = chart_plane(piece.frame, m);
        if (!plane) throw SceneError("generators: a lune piece's wall is its chart's horizon");
        planes.push_back(*plane);
        piece.walls.push_back({*plane, wall.internal, wall.index});
      }
      piece.polyhedron = make_polyhedron(planes, tolerance);
      bool tetrahedron = piece.polyhedron.bounded && piece.polyhedron.vertices.size() == 4;
      for (const auto& face : piece.polyhedron.faces) tetrahedron = tetrahedron && face.size() == 3;
      if (!tetrahedron)
        throw SceneError("generators: lune piece " + std::to_string(index) + " is not a tetrahedron");
      pieces.push_back(std::move(piece));
    }
  return pieces;
}

}  // namespace geodesic
