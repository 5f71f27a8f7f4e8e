#include "scene/cusp_neighbourhoods.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/scene.h"

namespace geodesic {
namespace {

constexpr auto kH3 = GeometryKind::Hyperbolic;

}  // namespace

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
