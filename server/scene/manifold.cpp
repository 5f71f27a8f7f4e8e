#include "scene/manifold.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>

#include "scene/scene.h"

namespace geodesic {
namespace {

constexpr double kPi = std::numbers::pi;

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", x);
  return buf;
}
std::string short_num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", x);
  return buf;
}
std::string degrees(double radians) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", radians * 180 / std::numbers::pi);
  return buf;
}
std::string face_path(int f) { return "manifold.faces[" + std::to_string(f) + "]"; }

std::vector<ChartPlane> planes_of(const std::vector<DomainFace>& faces) {
  std::vector<ChartPlane> planes;
  for (const DomainFace& f : faces) planes.push_back({f.normal, f.delta});
  return planes;
}

double distance_from_identity(const Mat4& g) {
  Mat4 d = g;
  for (int i = 0; i < 4; ++i) d.m[i][i] -= 1;
  return d.max_abs();
}

// Face distance in the chart of a regular dodecahedron with interior dihedral angle theta.
// Face f is the hyperplane with normal (N_f, s k) (s = +1 in H3's Lorentzian form, -1 in S3's
// Euclidean one), so cos theta = (s k^2 - c) / (1 - s k^2) with c = 1/sqrt 5 the cosine between
// adjacent N_f; solved for k: s k^2 = (c + cos theta) / (1 + cos theta).
double dodecahedron_chart_distance(GeometryKind kind, double dihedral) {
  const double c = 1 / std::sqrt(5.0), s = kind == GeometryKind::Hyperbolic ? 1 : -1;
  return std::sqrt(s * (c + std::cos(dihedral)) / (1 + std::cos(dihedral)));
}

// A regular dodecahedron with opposite faces glued by a right-handed screw motion along the
// inward normal -n_f: translation by twice the in-radius composed with a turn by `twist` about
// -n_f. The two senses are mirror images; one sense for all faces makes the edge cycles close.
Manifold twisted_dodecahedron(const char* name, GeometryKind kind, double dihedral, double twist) {
  const double k = dodecahedron_chart_distance(kind, dihedral);
  // Geodesic distance from the origin to the face plane: atanh k in H3, atan k in S3.
  const double in_radius = kind == GeometryKind::Hyperbolic ? std::atanh(k) : std::atan(k);
  std::vector<DomainFace> faces;
  const auto normals = dodecahedron_normals();
  for (std::size_t f = 0; f < normals.size(); ++f) {
    const Vec3 n = normals[f];
    const Mat4 g = model::translation(kind, -2 * in_radius * n) * model::rotation(n, -twist);
    faces.push_back({n, k, g, static_cast<int>(f ^ 1)});
  }
  Manifold m = make_generic(kind, std::move(faces));
  m.name = name;
  return m;
}

// Interior dihedral angle at edge e, from the model normals of its two faces at its midpoint.
double dihedral(GeometryKind kind, const std::vector<DomainFace>& faces, const Polyhedron& domain,
                int e) {
  const auto& [a, b] = domain.edges[e];
  const Vec4 q = model::lift(kind, (domain.vertices[a] + domain.vertices[b]) / 2.0);
  const auto on = edge_faces(domain, e);
  const DomainFace &fa = faces[on.at(0)], &fb = faces[on.at(1)];
  const double c = model::inner(kind, model::chart_plane_normal(kind, q, fa.normal, fa.delta),
                                model::chart_plane_normal(kind, q, fb.normal, fb.delta));
  return kPi - std::acos(std::clamp(c, -1.0, 1.0));
}

// The domain's vertices as model points, and lookup of a model point among them. An ideal
// vertex (a cusp, polyhedron.h) is the null vector (chart point, 1); its images are compared
// in the chart, finite ones by geodesic distance.
struct LiftedVertices {
  GeometryKind kind;
  std::vector<Vec4> points;
  std::vector<bool> ideal;

  LiftedVertices(GeometryKind k, const Polyhedron& p) : kind(k) {
    for (const Vec3& v : p.vertices) {
      ideal.push_back(ideal_vertex(k, v));
      points.push_back(ideal.back() ? Vec4(v, 1) : model::lift(k, v));
    }
  }
  // The image of vertex i under g.
  Vec4 image(const Mat4& g, int i) const {
    const Vec4 x = g * points[i];
    return ideal[i] ? x / x.w : model::normalize_point(kind, x);
  }
  double distance(const Vec4& x, int i) const {
    return ideal[i] ? length(x.xyz() / x.w - points[i].xyz())
                    : model::geodesic_distance(kind, x, points[i]);
  }
  // Index of the vertex nearest the image of vertex `from` under g among `candidates` (ideal
  // or finite alike), and its distance.
  std::pair<int, double> nearest(const Mat4& g, int from, const std::vector<int>& candidates) const {
    const Vec4 x = image(g, from);
    std::pair<int, double> best{-1, INFINITY};
    for (int i : candidates) {
      if (ideal[i] != ideal[from]) continue;
      const double d = distance(x, i);
      if (d < best.second) best = {i, d};
    }
    return best;
  }
};

// Edge cycles of a domain (see EdgeCycle); `slack` is the vertex matching distance.
std::vector<EdgeCycle> cycles_of(GeometryKind kind, const std::vector<DomainFace>& faces,
                                 const Polyhedron& domain, double slack) {
  const LiftedVertices lifted(kind, domain);
  const int ne = static_cast<int>(domain.edges.size());
  std::vector<int> all_vertices(domain.vertices.size());
  for (std::size_t i = 0; i < all_vertices.size(); ++i) all_vertices[i] = static_cast<int>(i);
  std::vector<std::vector<int>> faces_of_edge(ne);
  for (int e = 0; e < ne; ++e) {
    faces_of_edge[e] = edge_faces(domain, e);
    if (faces_of_edge[e].size() != 2)
      throw SceneError("manifold: edge " + std::to_string(e) + " lies on " +
                       std::to_string(faces_of_edge[e].size()) + " faces, not 2");
  }
  auto find_edge = [&](int a, int b) {
    for (int e = 0; e < ne; ++e)
      if ((domain.edges[e][0] == a && domain.edges[e][1] == b) ||
          (domain.edges[e][0] == b && domain.edges[e][1] == a))
        return e;
    return -1;
  };

  // visited[e][i]: the pair (edge e, its face faces_of_edge[e][i]) already lies on a cycle.
  std::vector<std::array<bool, 2>> visited(ne, {false, false});
  auto mark = [&](int e, int f) { visited[e][faces_of_edge[e][0] == f ? 0 : 1] = true; };
  std::vector<EdgeCycle> cycles;
  for (int e0 = 0; e0 < ne; ++e0)
    for (int slot = 0; slot < 2; ++slot) {
      if (visited[e0][slot]) continue;
      const int f0 = faces_of_edge[e0][slot];
      EdgeCycle cycle;
      cycle.transformation = Mat4::identity();
      int e = e0, f = f0;
      do {
        if (static_cast<int>(cycle.edges.size()) > 2 * ne)
          throw SceneError(face_path(f0) + ": the edge cycle of edge " + std::to_string(e0) +
                           " does not close");
        mark(e, f);
        cycle.edges.push_back(e);
        cycle.faces.push_back(f);
        cycle.angle_sum += dihedral(kind, faces, domain, e);
        const Mat4& g = faces[f].pairing;
        cycle.transformation = g * cycle.transformation;
        const int p = faces[f].partner;
        const auto a = lifted.nearest(g, domain.edges[e][0], all_vertices);
        const auto b = lifted.nearest(g, domain.edges[e][1], all_vertices);
        const int image = find_edge(a.first, b.first);
        if (a.second > slack || b.second > slack || image < 0 ||
            std::find(faces_of_edge[image].begin(), faces_of_edge[image].end(), p) ==
                faces_of_edge[image].end())
          throw SceneError(face_path(f) + ".pairing: does not map edge " + std::to_string(e) +
                           " onto an edge of face " + std::to_string(p));
        mark(image, p);  // the same class, walked the other way
        e = image;
        f = faces_of_edge[image][0] == p ? faces_of_edge[image][1] : faces_of_edge[image][0];
      } while (e != e0 || f != f0);
      if (cycle.angle_sum > 0)
        cycle.order = static_cast<int>(std::lround(2 * kPi / cycle.angle_sum));
      cycles.push_back(std::move(cycle));
    }
  return cycles;
}

// Checks of one face's pairing against its partner face (see validate_manifold).
void check_pairing(GeometryKind kind, const std::vector<DomainFace>& faces,
                   const Polyhedron& domain, const LiftedVertices& lifted, int f, double tol,
                   double slack) {
  const DomainFace& face = faces[f];
  const int p = face.partner;
  const std::string path = face_path(f);
  // Round-off in g^T G g grows with |g|^2 (E3: only the linear part enters).
  const double size = std::max(1.0, face.pairing.max_abs());
  const double bound = tol * (kind == GeometryKind::Euclidean ? 1 : size * size);
  const double error = model::isometry_error(kind, face.pairing);
  if (!(error <= bound))
    throw SceneError(path + ".pairing: not an isometry of " + geometry_name(kind) +
                     " space (error " + sci(error) + " > " + short_num(bound) + ")");
  if (faces[p].partner != f)
    throw SceneError(path + ".partner: face " + std::to_string(p) + "'s partner is " +
                     std::to_string(faces[p].partner) + ", not " + std::to_string(f) +
                     " (pairings must be mutual)");

  const auto& mine = domain.faces[f];
  const auto& theirs = domain.faces[p];
  const std::string onto =
      "does not map face " + std::to_string(f) + " onto face " + std::to_string(p);
  if (mine.size() != theirs.size())
    throw SceneError(path + ".pairing: " + onto + " (they have " + std::to_string(mine.size()) +
                     " and " + std::to_string(theirs.size()) + " vertices)");
  double off = 0, moved = 0;
  for (int i : mine) {
    off = std::max(off, lifted.nearest(face.pairing, i, theirs).second);
    moved = std::max(moved, lifted.distance(lifted.image(face.pairing, i), i));
  }
  if (off > slack)
    throw SceneError(path + ".pairing: " + onto + " (vertex off by " + sci(off) + ")");

  const Mat4 round_trip = faces[p].pairing * face.pairing;
  const double loop_error = distance_from_identity(round_trip);
  const double loop_bound = tol * size * size;
  if (p == f) {
    // Fixing the face pointwise with g . g = I leaves only the reflection (or the identity,
    // which the direction check below rejects).
    if (loop_error > loop_bound || moved > slack)
      throw SceneError(path +
                       ".pairing: a face paired with itself needs the reflection in its "
                       "plane (g . g - I: " +
                       sci(loop_error) + ", a vertex moves by " + sci(moved) + ")");
  } else if (loop_error > loop_bound) {
    throw SceneError(path + ": g_" + std::to_string(p) + " . g_" + std::to_string(f) +
                     " is not the identity (error " + sci(loop_error) + ")");
  }

  // A ray leaving through the middle of face f must come back into the domain through p.
  Vec3 centre;
  for (int i : mine) centre += domain.vertices[i];
  const Vec4 q = model::lift(kind, centre / static_cast<double>(mine.size()));
  const Vec4 out = model::chart_plane_normal(kind, q, face.normal, face.delta);
  const Vec4 q2 = model::normalize_point(kind, face.pairing * q);
  const double outward =
      model::inner(kind, face.pairing * out,
                   model::chart_plane_normal(kind, q2, faces[p].normal, faces[p].delta));
  if (outward > 0)
    throw SceneError(path + ".pairing: a ray leaving through face " + std::to_string(f) +
                     " leaves again through face " + std::to_string(p) +
                     " instead of entering the domain");
}

}  // namespace

std::vector<Vec3> dodecahedron_normals() {
  constexpr double phi = std::numbers::phi;
  std::vector<Vec3> normals;
  for (int axis = 0; axis < 3; ++axis)
    for (const Vec3& base : {Vec3{0, 1, phi}, Vec3{0, 1, -phi}})
      for (const double sign : {1.0, -1.0}) {
        const Vec3 v = sign * base;  // then its opposite
        const Vec3 cyclic[3] = {v, {v.z, v.x, v.y}, {v.y, v.z, v.x}};
        normals.push_back(normalize(cyclic[axis]));
      }
  return normals;
}

Manifold make_generic(GeometryKind /*same polyhedron in every chart*/,
                      std::vector<DomainFace> faces, double tolerance) {
  Manifold m;
  m.name = "generic";
  m.domain = make_polyhedron(planes_of(faces), tolerance);
  m.faces = std::move(faces);
  return m;
}

Manifold make_torus(GeometryKind kind, double half_size) {
  if (kind != GeometryKind::Euclidean)
    throw SceneError(std::string("the 3-torus is a euclidean manifold, not ") +
                     geometry_name(kind));
  std::vector<DomainFace> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {1.0, -1.0}) {
      Vec3 n;
      (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = sign;
      const int f = static_cast<int>(faces.size());
      faces.push_back({n, half_size, model::translation(kind, -2 * half_size * n), f ^ 1});
    }
  Manifold m = make_generic(kind, std::move(faces));
  m.name = "torus";
  return m;
}

Manifold make_mirrored_dodecahedron() {
  constexpr auto kind = GeometryKind::Hyperbolic;
  const double k = dodecahedron_chart_distance(kind, kPi / 2);  // = 5^(-1/4)
  std::vector<DomainFace> faces;
  for (const Vec3& n : dodecahedron_normals()) {
    const int f = static_cast<int>(faces.size());
    faces.push_back({n, k, model::reflection_in_chart_plane(kind, n, k), f});
  }
  Manifold m = make_generic(kind, std::move(faces));
  m.name = "mirrored-dodecahedron";
  return m;
}

Manifold make_poincare_dodecahedral_space() {
  // Screw by pi/5 = 2 . in-radius with a pi/5 twist: left multiplication by the unit
  // quaternion cos(pi/5) - sin(pi/5) n_f (checked against the quaternion in the tests).
  return twisted_dodecahedron("poincare-dodecahedral", GeometryKind::Spherical, 2 * kPi / 3,
                              kPi / 5);
}

Manifold make_seifert_weber_space() {
  return twisted_dodecahedron("seifert-weber", GeometryKind::Hyperbolic, 2 * kPi / 5, 3 * kPi / 5);
}

std::vector<IdealVertexPairing> ideal_vertex_pairings(GeometryKind kind, const Manifold& m,
                                                      double tolerance) {
  const LiftedVertices lifted(kind, m.domain);
  std::vector<IdealVertexPairing> found;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int i : m.domain.faces[f]) {
      if (!lifted.ideal[i]) continue;
      const auto [j, off] =
          lifted.nearest(m.faces[f].pairing, i, m.domain.faces[m.faces[f].partner]);
      if (j >= 0 && off <= tolerance * 100) found.push_back({static_cast<int>(f), i, j});
    }
  return found;
}

std::vector<std::vector<int>> cusps(GeometryKind kind, const Manifold& m, double tolerance) {
  std::vector<int> parent(m.domain.vertices.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const IdealVertexPairing& p : ideal_vertex_pairings(kind, m, tolerance))
    parent[root(p.from)] = root(p.to);
  std::vector<std::vector<int>> classes;
  std::vector<int> index(parent.size(), -1);
  for (std::size_t i = 0; i < parent.size(); ++i) {
    if (!ideal_vertex(kind, m.domain.vertices[i])) continue;
    int& k = index[root(static_cast<int>(i))];
    if (k < 0) {
      k = static_cast<int>(classes.size());
      classes.emplace_back();
    }
    classes[k].push_back(static_cast<int>(i));
  }
  return classes;
}

double dihedral_angle(GeometryKind kind, const Manifold& m, int e) {
  return dihedral(kind, m.faces, m.domain, e);
}

std::vector<EdgeCycle> edge_cycles(GeometryKind kind, const Manifold& m, double tolerance) {
  return cycles_of(kind, m.faces, m.domain, tolerance * 100);
}

void validate_manifold(GeometryKind kind, const Manifold& m, double tol) {
  if (m.max_crossings < 0 || m.max_crossings > kMaxCrossings)
    throw SceneError("manifold.max_crossings: must be in [0, " + std::to_string(kMaxCrossings) + "]");
  if (m.faces.empty()) return;
  const int n = static_cast<int>(m.faces.size());
  for (int f = 0; f < n; ++f) {
    const DomainFace& face = m.faces[f];
    if (std::abs(length(face.normal) - 1) > tol)
      throw SceneError(face_path(f) + ".normal: must be a unit vector (length " +
                       std::to_string(length(face.normal)) + ")");
    if (face.partner < 0 || face.partner >= n)
      throw SceneError(face_path(f) + ".partner: there is no face " + std::to_string(face.partner) +
                       " (faces are 0 to " + std::to_string(n - 1) + ")");
    for (int g = 0; g < f; ++g)
      if (length(face.normal - m.faces[g].normal) < tol &&
          std::abs(face.delta - m.faces[g].delta) < tol * std::max(1.0, std::abs(face.delta)))
        throw SceneError(face_path(f) + ": the same plane as face " + std::to_string(g));
  }

  // The domain, recomputed so that it cannot disagree with the faces.
  const Polyhedron domain = make_polyhedron(planes_of(m.faces), tol);
  if (!domain.bounded)
    throw SceneError("manifold: the domain is unbounded (some direction crosses no face)");
  if (domain.vertices.empty())
    throw SceneError("manifold: the domain is empty (the faces' half-spaces do not meet)");
  double scale = 1;
  for (int f = 0; f < n; ++f) {
    scale = std::max(scale, std::abs(m.faces[f].delta));
    if (domain.faces[f].size() < 3)
      throw SceneError(face_path(f) + ": its plane does not bound the domain (it touches " +
                       std::to_string(domain.faces[f].size()) + " vertices)");
  }
  if (kind == GeometryKind::Hyperbolic)
    for (std::size_t i = 0; i < domain.vertices.size(); ++i) {
      const double r = length(domain.vertices[i]);
      if (r > 1 + kIdealTolerance)
        throw SceneError("manifold: the domain reaches beyond the sphere at infinity (vertex " +
                         std::to_string(i) + " at Klein radius " + std::to_string(r) +
                         " > 1): its volume is infinite; only cusps, vertices on the sphere, are "
                         "allowed");
    }

  const double slack = tol * scale * 100;  // vertex matching, after a few products
  const LiftedVertices lifted(kind, domain);
  for (int f = 0; f < n; ++f) check_pairing(kind, m.faces, domain, lifted, f, tol, slack);

  // Poincare's condition: the copies of the domain around every edge close up.
  const double angle_tol = std::max(1e-9, 1e3 * tol);
  for (const EdgeCycle& c : cycles_of(kind, m.faces, domain, slack)) {
    const auto faces = edge_faces(domain, c.edges[0]);
    const std::string where = face_path(c.faces[0]) + ": the edge cycle of edge " +
                              std::to_string(c.edges[0]) + " (faces " + std::to_string(faces[0]) +
                              " and " + std::to_string(faces[1]) + ")";
    if (c.order < 1 || std::abs(c.angle_sum * c.order - 2 * kPi) > angle_tol * c.order)
      throw SceneError(where + " has dihedral angles summing to " + degrees(c.angle_sum) +
                       " degrees, not 360 / k for a whole k (a wrong twist?)");
    Mat4 power = Mat4::identity();
    double size = 1;
    for (int i = 0; i < c.order; ++i) {
      power = c.transformation * power;
      size = std::max(size, power.max_abs());
    }
    const double error = distance_from_identity(power);
    if (error > 1e3 * tol * size * size)
      throw SceneError(where + ": its transformation h has h^" + std::to_string(c.order) +
                       " != I (error " + sci(error) + ")");
  }
}

}  // namespace geodesic
