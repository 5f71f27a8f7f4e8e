#include "scene/chart_atlas.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "scene/atlas_piece.h"
#include "scene/plane_clipping.h"
#include "scene/scene.h"

namespace geodesic {
namespace {

constexpr auto kS3 = GeometryKind::Spherical;
constexpr std::size_t kMaxPieceFaces = 256;
// Each piece is a cell of the renderer, with its own acceleration-structure instances; past
// eight cells they share mask bits and the shaders filter candidates by cell
// (SHARED_CELL_MASKS, docs/pipelines.md).
constexpr std::size_t kMaxPieces = 256;

double distance4(const Vec4& a, const Vec4& b) { return std::sqrt(dot(a - b, a - b)); }

int find_point(const std::vector<Vec4>& points, const Vec4& p) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (distance4(points[i], p) < 1e-9) return static_cast<int>(i);
  return -1;
}

bool same_plane(const ChartPlane& a, const ChartPlane& b, double tolerance) {
  return dot(a.normal, b.normal) > 1 - tolerance &&
         std::abs(a.delta - b.delta) < tolerance * std::max(1.0, std::abs(a.delta));
}

// A frame off every axis, so that no Voronoi wall falls on a bisector of the origin's orbit.
std::vector<Vec4> frame_axes() {
  const Mat4 turn = model::rotation(normalize(Vec3{0.37, 0.61, 0.71}), 0.53) *
                    model::translation(kS3, {0.29, -0.17, 0.41});
  std::vector<Vec4> axes;
  for (int i = 0; i < 4; ++i)
    for (const double sign : {1.0, -1.0}) {
      const Vec4 e{i == 0 ? sign : 0, i == 1 ? sign : 0, i == 2 ? sign : 0, i == 3 ? sign : 0};
      axes.push_back(turn * e);
    }
  return axes;
}

std::optional<AtlasPiece> make_piece(const std::vector<GroupElement>& elements,
                                const std::vector<Vec4>& centres, int c, double tolerance) {
  AtlasPiece piece{c, model::translation_from(kS3, centres[c]), {}, {}};
  std::vector<AtlasWall> walls;
  for (int t = 0; t < static_cast<int>(centres.size()); ++t) {
    // Voronoi cells lie within pi/3 of their centres: only centres within 2 pi / 3 are walls.
    if (t == c || dot(centres[t], centres[c]) < -0.5 - 1e-9) continue;
    if (const auto plane = chart_plane(piece.frame, centres[t] - centres[c]))
      walls.push_back({*plane, true, t});
  }
  for (int i = 1; i < static_cast<int>(elements.size()); ++i) {
    const Vec4 m = elements[i].point - model::origin();
    const auto plane = chart_plane(piece.frame, m);
    if (plane) walls.push_back({*plane, false, i});
    else if ((piece.frame * m).w > 0) return std::nullopt;  // the whole chart lies outside D
  }
  // A mirror r of the group is also the Voronoi wall between s and r s. If D lies on s's side
  // the face must carry r's gluing, so the Voronoi copy of the plane goes; if it lies beyond,
  // the piece would be flat.
  for (const AtlasWall& b : walls)
    for (const AtlasWall& v : walls)
      if (!b.internal && v.internal && same_plane(b.plane, {-v.plane.normal, -v.plane.delta}, tolerance))
        return std::nullopt;
  std::erase_if(walls, [&](const AtlasWall& v) {
    return v.internal && std::any_of(walls.begin(), walls.end(), [&](const AtlasWall& b) {
             return !b.internal && same_plane(v.plane, b.plane, tolerance);
           });
  });
  std::sort(walls.begin(), walls.end(),
            [](const AtlasWall& a, const AtlasWall& b) { return a.plane.delta < b.plane.delta; });
  std::vector<ChartPlane> planes;
  for (const AtlasWall& w : walls) planes.push_back(w.plane);
  const ClippedPolyhedron clipped = clip_planes(planes, tolerance, INFINITY, kMaxPieceFaces);
  if (!clipped.polyhedron.bounded && clipped.kept.size() >= kMaxPieceFaces)
    throw SceneError("generators: a chart piece of the domain needs more than " +
                     std::to_string(kMaxPieceFaces) + " faces (the group has " +
                     std::to_string(elements.size()) + " elements and preserves a great circle); " +
                     "a smaller group renders");
  if (!clipped.polyhedron.bounded || clipped.polyhedron.vertices.size() < 4) return std::nullopt;
  piece.polyhedron = clipped.polyhedron;
  for (int k : clipped.kept) piece.walls.push_back(walls[k]);
  return piece;
}

// Largest distance from a face's vertices, carried by g, to the partner face's vertices.
double mismatch(const AtlasPiece& from, int face, const AtlasPiece& to, int partner, const Mat4& g) {
  double worst = 0;
  for (int v : from.polyhedron.faces[face]) {
    const Vec4 x = model::inverse_isometry(kS3, from.frame) * model::lift(kS3, from.polyhedron.vertices[v]);
    const Vec4 image = to.frame * (g * x);
    double nearest = INFINITY;
    for (int u : to.polyhedron.faces[partner])
      nearest = std::min(nearest, distance4(model::normalize_point(kS3, image),
                                            model::lift(kS3, to.polyhedron.vertices[u])));
    worst = std::max(worst, nearest);
  }
  return worst;
}

// The Voronoi cut (header): the pieces D n V_s, with piece_of[s] the piece of centre s.
std::vector<AtlasPiece> voronoi_pieces(const std::vector<GroupElement>& elements, double tolerance,
                                       std::vector<Vec4>& centres, std::vector<int>& piece_of) {
  const std::vector<Vec4> axes = frame_axes();
  for (const GroupElement& e : elements)
    for (const Vec4& a : axes) {
      const Vec4 p = model::normalize_point(kS3, e.g * a);
      if (find_point(centres, p) < 0) centres.push_back(p);
    }
  std::vector<AtlasPiece> pieces;
  piece_of.assign(centres.size(), -1);
  for (int c = 0; c < static_cast<int>(centres.size()); ++c)
    if (auto piece = make_piece(elements, centres, c, tolerance)) {
      piece_of[c] = static_cast<int>(pieces.size());
      pieces.push_back(std::move(*piece));
      if (pieces.size() > kMaxPieces)
        throw SceneError("generators: the domain needs more than " + std::to_string(kMaxPieces) +
                         " chart pieces (the group preserves a great circle, so no single chart "
                         "holds its domain), and the renderer keeps at most " +
                         std::to_string(kMaxPieces) + " cells");
    }
  return pieces;
}

}  // namespace

Manifold chart_atlas_manifold(const std::vector<GroupElement>& elements, double tolerance) {
  std::vector<Vec4> points;  // the elements' images of the origin, to find inverses
  for (const GroupElement& e : elements) points.push_back(e.point);
  auto inverse_of = [&](int i) {
    return find_point(points, model::inverse_isometry(kS3, elements[i].g) * model::origin());
  };
  std::vector<Vec4> centres;
  std::vector<int> piece_of;
  std::vector<AtlasPiece> pieces;
  if (auto lune = lune_pieces(elements, tolerance)) {
    pieces = std::move(*lune);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      centres.push_back(model::inverse_isometry(kS3, pieces[i].frame) * model::origin());
      piece_of.push_back(static_cast<int>(i));
    }
  } else {
    pieces = voronoi_pieces(elements, tolerance, centres, piece_of);
  }

  Manifold m;
  m.name = "generators";
  std::vector<int> first_face;
  int faces = 0;
  for (const AtlasPiece& p : pieces) {
    first_face.push_back(faces);
    faces += static_cast<int>(p.walls.size());
  }
  auto face_of = [&](int piece, bool internal, int index) {
    const auto& walls = pieces[piece].walls;
    for (std::size_t k = 0; k < walls.size(); ++k)
      if (walls[k].internal == internal && walls[k].index == index) return static_cast<int>(k);
    return -1;
  };
  std::vector<int> domain_faces;  // elements whose bisector bounds D
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    DomainPiece out{pieces[p].frame, {}, pieces[p].polyhedron};
    for (std::size_t k = 0; k < pieces[p].walls.size(); ++k) {
      const AtlasWall& w = pieces[p].walls[k];
      Mat4 g = Mat4::identity();
      int target = -1, partner = -1;
      if (w.internal) {
        target = piece_of[w.index];
        if (target >= 0) partner = face_of(target, true, pieces[p].centre);
      } else {
        const int inverse = inverse_of(w.index);
        g = model::reorthonormalize(kS3, model::inverse_isometry(kS3, elements[w.index].g));
        const int centre = find_point(centres, model::normalize_point(kS3, g * centres[pieces[p].centre]));
        target = centre >= 0 ? piece_of[centre] : -1;
        if (target >= 0 && inverse >= 0) partner = face_of(target, false, inverse);
        if (partner >= 0 && mismatch(pieces[p], int(k), pieces[target], partner, g) > 100 * tolerance)
          partner = -1;
        // No piece holds g's image of this piece's centre: a mirror's piece faces the mirror
        // image of its centre, whose cell lies beyond the mirror, and a lune's pieces turn
        // with its twist. The partner is then the face of g^-1 that g carries this one onto.
        for (int q = 0; partner < 0 && inverse >= 0 && q < static_cast<int>(pieces.size()); ++q) {
          const int f = face_of(q, false, inverse);
          if (f >= 0 && mismatch(pieces[p], int(k), pieces[q], f, g) <= 100 * tolerance)
            target = q, partner = f;
        }
        if (std::find(domain_faces.begin(), domain_faces.end(), w.index) == domain_faces.end())
          domain_faces.push_back(w.index);
      }
      const std::string where = "generators: piece " + std::to_string(p) + " face " + std::to_string(k);
      if (partner < 0)
        throw SceneError(where + " has no partner face in the chart atlas");
      const double off = mismatch(pieces[p], int(k), pieces[target], partner, g);
      if (off > 100 * tolerance)
        throw SceneError(where + ": its gluing misses the partner face by " + std::to_string(off));
      out.faces.push_back({w.plane.normal, w.plane.delta, g, target, first_face[target] + partner, w.internal});
    }
    m.pieces.push_back(std::move(out));
  }
  // D's faces as planes of the origin's chart (for containment tests near the origin); the
  // antipode's bisector is that chart's horizon and has no plane there.
  std::vector<int> charted;
  for (int i : domain_faces)
    if (length(elements[i].point.xyz()) > 1e-12) charted.push_back(i);
  for (int i : charted) {
    const Vec4 a = elements[i].point;
    const double s = length(a.xyz());
    const auto partner = std::find(charted.begin(), charted.end(), inverse_of(i));
    m.faces.push_back({a.xyz() / s, (1 - a.w) / s,
                       model::reorthonormalize(kS3, model::inverse_isometry(kS3, elements[i].g)),
                       static_cast<int>(partner - charted.begin())});
  }
  return m;
}

}  // namespace geodesic
