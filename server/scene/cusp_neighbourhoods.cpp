#include "scene/cusp_neighbourhoods.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/scene.h"

namespace geodesic {
namespace {

constexpr auto kH3 = GeometryKind::Hyperbolic;

struct Point2 {
  double x, y;
};

// The part of `polygon` where a + b x + c y <= 0 (Sutherland-Hodgman, one edge).
std::vector<Point2> clip(const std::vector<Point2>& polygon, double a, double b, double c) {
  std::vector<Point2> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
    const double fp = a + b * p.x + c * p.y, fq = a + b * q.x + c * q.y;
    if (fp <= 0) out.push_back(p);
    if ((fp < 0) != (fq < 0) && fp != fq) {
      const double s = fp / (fp - fq);
      out.push_back({p.x + s * (q.x - p.x), p.y + s * (q.y - p.y)});
    }
  }
  return out;
}

}  // namespace

double horosphere_area_in_domain(const Manifold& m, const Vec4& l) {
  const double d = std::log(l.w);
  const Vec3 n = l.xyz() / l.w;
  const Vec4 x0(std::sinh(d) * n, std::cosh(d));
  const Vec3 p1 = normalize(std::abs(n.x) < 0.9 ? cross(n, Vec3{1, 0, 0}) : cross(n, Vec3{0, 1, 0}));
  const Vec3 p2 = cross(n, p1);
  constexpr double kBound = 1e4;  // a polygon reaching it is unbounded
  std::vector<Point2> polygon{{-kBound, -kBound}, {kBound, -kBound}, {kBound, kBound}, {-kBound, kBound}};
  for (const DomainFace& f : m.faces) {
    // The face's half-space dot(normal, x) - delta w <= 0, linear in x; through the ideal
    // point it vanishes on l, and x0 + u + |u|^2 / 2 l gives a line in u.
    if (std::abs(dot(f.normal, n) - f.delta) > 1e-6) continue;
    polygon = clip(polygon, dot(f.normal, x0.xyz()) - f.delta * x0.w, dot(f.normal, p1),
                   dot(f.normal, p2));
  }
  double area = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
    if (std::max({std::abs(p.x), std::abs(p.y)}) >= kBound / 2) return INFINITY;
    area += p.x * q.y - q.x * p.y;
  }
  return polygon.size() < 3 ? INFINITY : std::abs(area) / 2;
}

std::vector<CuspHorosphere> cusp_horospheres(const Manifold& m, double margin, double clearance) {
  const std::vector<std::vector<int>> classes = cusps(kH3, m);
  const std::vector<IdealVertexPairing> pairings = ideal_vertex_pairings(kH3, m);
  const Polyhedron& p = m.domain;
  std::vector<Vec4> l(p.vertices.size());
  std::vector<int> cusp_of(p.vertices.size(), -1);
  for (std::size_t k = 0; k < classes.size(); ++k) {
    // Spread l from the class's first vertex across the faces' pairings.
    const int first = classes[k][0];
    l[first] = Vec4(normalize(p.vertices[first]), 1);
    cusp_of[first] = static_cast<int>(k);
    std::vector<int> queue{first};
    while (!queue.empty()) {
      const int i = queue.back();
      queue.pop_back();
      for (const IdealVertexPairing& pairing : pairings) {
        if (pairing.from != i) continue;
        const Vec4 image = m.faces[pairing.face].pairing * l[i];
        const int j = pairing.to;
        if (cusp_of[j] < 0) {
          cusp_of[j] = static_cast<int>(k);
          l[j] = image;
          queue.push_back(j);
        } else if (std::abs(image.w / l[j].w - 1) > 1e-6) {
          throw SceneError("manifold: cusp " + std::to_string(k) +
                           " is incomplete: going round it scales its horospheres by " +
                           std::to_string(image.w / l[j].w) +
                           " (the face pairings' holonomy there is not a Euclidean motion)");
        }
      }
    }
  }
  // Words of at most two pairings (and none): the images nearest the domain.
  std::vector<Mat4> words{Mat4::identity()};
  for (const DomainFace& f : m.faces) words.push_back(f.pairing);
  for (const DomainFace& f : m.faces)
    for (const DomainFace& g : m.faces) words.push_back(f.pairing * g.pairing);
  double closest = INFINITY;  // the smallest -<l_i, w l_j> over distinct ideal points
  for (std::size_t i = 0; i < l.size(); ++i) {
    if (cusp_of[i] < 0) continue;
    for (std::size_t j = 0; j < l.size(); ++j) {
      if (cusp_of[j] < 0) continue;
      for (const Mat4& w : words) {
        const Vec4 image = w * l[j];
        if (length(image.xyz() / image.w - l[i].xyz() / l[i].w) < 1e-6) continue;  // same point
        closest = std::min(closest, -model::inner(kH3, l[i], image));
      }
    }
  }
  // Scale s with s^2 closest = 2 makes the nearest two tangent; e^margin more moves each
  // horosphere `margin` deeper; one at distance log(l.w) from the origin is `clearance` away
  // when l.w = e^clearance.
  double scale = std::isfinite(closest) ? std::sqrt(2 / closest) * std::exp(margin) : 1;
  for (std::size_t i = 0; i < l.size(); ++i)
    if (cusp_of[i] >= 0) scale = std::max(scale, std::exp(clearance) / l[i].w);
  std::vector<CuspHorosphere> out;
  for (std::size_t i = 0; i < l.size(); ++i)
    if (cusp_of[i] >= 0)
      out.push_back({cusp_of[i], static_cast<int>(i), l[i].xyz() / l[i].w, std::log(scale * l[i].w)});
  return out;
}

}  // namespace geodesic
