// Quotient manifolds M / Gamma of the three model geometries, given by a fundamental domain
// (a convex polyhedron in the chart) and its face pairings (Novello et al. 2019, alg. 1): a
// ray leaving the domain through face f at model point q with tangent v continues as
// (g_f q, g_f v), on face partner(f), pointing into the domain.
#pragma once

#include <string>
#include <vector>

#include "geometry/model.h"
#include "geometry/vec.h"
#include "scene/polyhedron.h"

namespace geodesic {

struct DomainFace {
  Vec3 normal;       // outward unit normal in the chart
  double delta = 0;  // the face plane is normal . X = delta (chart)
  Mat4 pairing;      // carries a ray leaving through this face into the domain through `partner`
  int partner = 0;
};

// A spherical domain that no single gnomonic chart holds (scene/chart_atlas.h) is cut into
// pieces, each a convex polyhedron in the chart centred on `centre`; the renderer makes each a
// cell (render/prepare/cells.h). A ray leaving piece p through face f continues as (g q, g v) in piece
// `target`, entering through face `partner` (global index: pieces number faces in order).
struct PieceFace {
  Vec3 normal;  // outward unit normal in the piece's chart
  double delta = 0;
  Mat4 pairing;  // identity between pieces of the domain, a group element across its boundary
  int target = 0;
  int partner = 0;
  bool internal = false;  // a wall between pieces: crossing it starts no new copy of the domain
};
struct DomainPiece {
  Mat4 chart_isometry;  // model -> the piece's frame (its centre to the origin)
  std::vector<PieceFace> faces;
  Polyhedron polyhedron;  // in the piece's chart
};

// The most face crossings a ray may make (manifold.max_crossings).
inline constexpr int kMaxCrossings = 64;

struct Manifold {
  std::string name = "none";      // "none" for the whole space
  std::vector<DomainFace> faces;  // empty: no quotient
  int max_crossings = 16;         // face crossings per ray before it is dropped
  Polyhedron domain;              // chart vertices, edges (vertex index pairs), face polygons
  // Empty, or the domain cut into pieces charted apart (then `domain` is empty and `faces`
  // are the domain's faces as planes of the origin's chart, which holds only part of them).
  std::vector<DomainPiece> pieces;
};

// The cube [-h, h]^3 with opposite faces glued by translations by 2h (the paper's 3-torus).
// Faces +x, -x, +y, -y, +z, -z; euclidean only (throws SceneError otherwise).
Manifold make_torus(GeometryKind kind, double half_size);
// H3: the right-angled regular dodecahedron, every face glued to itself by the reflection in
// its plane (the paper's mirrored dodecahedral space; an orbifold, four cells per edge).
Manifold make_mirrored_dodecahedron();
// S3: the regular dodecahedron with dihedral angle 120 deg, opposite faces glued by 1/10 turns
// (left multiplication by the unit quaternion cos(pi/5) - sin(pi/5) n_f; the group is the
// binary icosahedral group, of order 120).
Manifold make_poincare_dodecahedral_space();
// H3: the regular dodecahedron with dihedral angle 72 deg, opposite faces glued by 3/10 turns.
Manifold make_seifert_weber_space();
// Any face list; computes the domain polyhedron (name "generic"). Does not validate.
Manifold make_generic(GeometryKind kind, std::vector<DomainFace> faces, double tolerance = 1e-9);

// The dodecahedra's faces: the 12 icosahedron vertices (0, +-1, +-phi) and their cyclic
// permutations, normalised, ordered so that face 2i+1 is opposite face 2i.
std::vector<Vec3> dodecahedron_normals();

// One class of edges under the face pairings (Poincare's polyhedron theorem): the edges met
// when following edge `edges[0]` from face `faces[0]` through g_faces[i] in turn until both
// return. The images of the domain around the edge close up when angle_sum = 2 pi / order
// with `order` a positive integer and the cycle transformation h satisfies h^order = I.
struct EdgeCycle {
  std::vector<int> edges;  // indices into domain.edges, one per step
  std::vector<int> faces;  // the face whose pairing is applied at each step
  double angle_sum = 0;    // interior dihedral angles at the edges, radians
  int order = 0;           // round(2 pi / angle_sum): 1 for a manifold's edges
  Mat4 transformation;     // h = g_faces[n-1] ... g_faces[0], fixing the edge
};
// Throws SceneError when a pairing does not map an edge onto an edge.
std::vector<EdgeCycle> edge_cycles(GeometryKind kind, const Manifold& m, double tolerance = 1e-9);

// Face f's pairing carries the domain's ideal vertex `from` (on face f) to `to` (on its
// partner face).
struct IdealVertexPairing {
  int face = 0, from = 0, to = 0;
};

// Every ideal vertex of every face with its image under the face's pairing (images compared
// in the chart within 100 x tolerance). Empty for a compact domain.
std::vector<IdealVertexPairing> ideal_vertex_pairings(GeometryKind kind, const Manifold& m,
                                                      double tolerance = 1e-9);

// The cusps of an H3 domain with ideal vertices (polyhedron.h): the classes of ideal vertices
// under the face pairings, each a list of vertex indices. Empty for a compact domain.
std::vector<std::vector<int>> cusps(GeometryKind kind, const Manifold& m, double tolerance = 1e-9);

// Interior dihedral angle of the domain at edge e (radians), measured in the model.
double dihedral_angle(GeometryKind kind, const Manifold& m, int e);

// Throws SceneError ("manifold...: reason") when the face list is not a valid fundamental
// domain: unbounded domain or one of infinite volume (ideal vertices, cusps, are allowed in H3;
// polyhedron.h), a face that bounds nothing, a pairing that is not an
// isometry or does not carry its face onto its partner (vertex set and inward direction),
// non-mutual pairings, or an edge cycle that does not close up. `tolerance` is relative: 1e-9
// for the closed-form bundled manifolds, about 1e-6 for matrices typed into a scene file.
void validate_manifold(GeometryKind kind, const Manifold& m, double tolerance = 1e-9);

}  // namespace geodesic
