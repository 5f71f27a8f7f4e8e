#include "scene/dirichlet_domain.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "scene/chart_atlas.h"
#include "scene/domain_volume.h"
#include "scene/group_orbit.h"
#include "scene/plane_clipping.h"
#include "scene/scene.h"

namespace geodesic {
namespace {

// Gnomonic chart radius beyond which an S3 domain counts as reaching the horizon: float
// rays lose too much there (tan 1.45 = 8.2, w = 0.12).
constexpr double kMaxSphericalCircumradius = 1.45;
// E3 and H3 spaces are infinite groups: the search radius grows to twice the circumradius,
// but gives up after this many doublings of the generators' displacement.
constexpr int kMaxGrowth = 12;
// In H3 no product reaching beyond this distance is enumerated: it loses so much double
// precision that two words for one element no longer agree (the powers of a single
// translation by 1 stop matching beyond distance 10, those of a translation by 12 already at
// 24, and the group then looks as if it fixed a point or had twice its elements).
constexpr double kHyperbolicPrecision = 10;
// The search radius stops here, short of that: slack for detours. Every H3 space of the
// catalogue and of Curved Spaces closes its cell well within it (CurvedSpacesFiles.*), so a
// cell still open here is an unbounded domain.
constexpr double kHyperbolicReach = 8;
// Planes of a cell still unbounded after this many are not closing it (make_polyhedron is
// quartic in the plane count; the scene format allows 64 faces).
constexpr std::size_t kMaxCuts = 64;

[[noreturn]] void fail(const std::string& reason) { throw SceneError("generators: " + reason); }

// The one answer for a discrete group with a non-compact quotient; `how` (in parentheses, when
// given) says how it was found.
[[noreturn]] void fail_unbounded(GeometryKind kind, const std::string& how = "") {
  const std::string why = kind == GeometryKind::Hyperbolic
                              ? " has infinite volume (the domain reaches the sphere at infinity "
                                "in more than the isolated points of cusps)"
                              : " is not compact";
  fail(std::string("the Dirichlet domain is unbounded: the quotient of ") + geometry_name(kind) +
       " space by these generators" + why + (how.empty() ? "" : " (" + how + ")"));
}

// The bisector of the origin and a = g . origin, as a chart plane with the origin inside:
// E3 a.X = |a|^2 / 2; H3 a.X = a_w - 1 (tanh(d/2) from the origin); S3 a.X = 1 - a_w
// (tan(d/2)). None in S3 for the antipode, whose bisector is the chart's horizon.
std::optional<ChartPlane> bisector(GeometryKind kind, const Vec4& a) {
  const double s = length(a.xyz());
  if (s < 1e-12) return std::nullopt;
  const Vec3 n = a.xyz() / s;
  switch (kind) {
    case GeometryKind::Hyperbolic: return ChartPlane{n, (a.w - 1) / s};
    case GeometryKind::Spherical: return ChartPlane{n, (1 - a.w) / s};
    case GeometryKind::Euclidean: break;
  }
  return ChartPlane{n, s / 2};
}

struct Cut {
  int element;
  ChartPlane plane;
};

struct Cell {
  std::vector<Cut> cuts;  // only the planes that bound a face
  Polyhedron polyhedron;
  double circumradius = INFINITY;  // of the finite vertices
  int ideal_vertices = 0;          // H3: vertices on the sphere at infinity (cusps' tips)
};

// The Dirichlet cell of the enumerated elements (clip_planes: bisectors nearest first; those
// beyond the circumradius cannot cut).
Cell dirichlet_cell(GeometryKind kind, const GroupOrbit& orbit, double tolerance) {
  std::vector<Cut> candidates;
  for (int i = 1; i < static_cast<int>(orbit.elements().size()); ++i)
    if (const auto plane = bisector(kind, orbit.elements()[i].point)) candidates.push_back({i, *plane});
  std::sort(candidates.begin(), candidates.end(),
            [](const Cut& a, const Cut& b) { return a.plane.delta < b.plane.delta; });
  std::vector<ChartPlane> planes;
  for (const Cut& c : candidates) planes.push_back(c.plane);
  const ClippedPolyhedron clipped = clip_planes(
      planes, tolerance, kind == GeometryKind::Hyperbolic ? 1 + kIdealTolerance : INFINITY,
      kMaxCuts);
  Cell cell;
  cell.polyhedron = clipped.polyhedron;
  for (int k : clipped.kept) cell.cuts.push_back(candidates[k]);
  if (!cell.polyhedron.bounded || cell.polyhedron.vertices.empty()) return cell;
  cell.circumradius = 0;
  for (const Vec3& v : cell.polyhedron.vertices) {
    if (ideal_vertex(kind, v)) {
      ++cell.ideal_vertices;
      continue;
    }
    cell.circumradius = std::max(cell.circumradius, displacement(kind, model::lift(kind, v)));
  }
  return cell;
}

// Faces, pairings and partners of the cell (see the header), then the checks.
Manifold manifold_of(GeometryKind kind, const GroupOrbit& orbit, const Cell& cell,
                     double tolerance, double& isometry_error) {
  std::vector<DomainFace> faces;
  isometry_error = 0;
  for (const Cut& c : cell.cuts) {
    const Mat4 inverse = model::reorthonormalize(
        kind, model::inverse_isometry(kind, orbit.elements()[c.element].g));
    isometry_error = std::max(isometry_error, model::isometry_error(kind, inverse));
    const int element = orbit.find(inverse * model::origin());
    int partner = -1;
    for (std::size_t f = 0; f < cell.cuts.size(); ++f)
      if (cell.cuts[f].element == element) partner = static_cast<int>(f);
    if (partner < 0)
      fail("the face of group element " + std::to_string(c.element) +
           " has no partner face (the inverse's bisector does not bound the cell): the "
           "generators do not form a discrete group, or too few elements were enumerated");
    faces.push_back({c.plane.normal, c.plane.delta, inverse, partner});
  }
  Manifold m = make_generic(kind, std::move(faces), tolerance);
  m.name = "generators";
  validate_manifold(kind, m, tolerance);
  return m;
}

// Whether g is a product of the face pairings of m: g . origin walked back into the domain,
// across the face it lies farthest beyond each time, comes to the origin itself. Each step
// brings the point nearer the origin (the face is the bisector of the origin and an image of
// it that the point is nearer to), so the walk ends. A cusped cell has no circumradius to bound
// the elements that could cut it; this is what tells it is complete instead: its pairings
// generate the group (then, with validate_manifold's edge cycles, Poincare's theorem makes the
// cell a fundamental domain, and so the Dirichlet domain).
bool generated_by_pairings(GeometryKind kind, const Manifold& m, const Mat4& g) {
  Vec4 p = g * model::origin();
  for (int step = 0; step < 4096; ++step) {
    int worst = -1;
    double beyond = 1e-9;
    const Vec3 x = p.xyz() / p.w;
    for (std::size_t f = 0; f < m.faces.size(); ++f)
      if (const double d = dot(m.faces[f].normal, x) - m.faces[f].delta; d > beyond) {
        beyond = d;
        worst = static_cast<int>(f);
      }
    if (worst < 0) return displacement(kind, p) < 1e-6;
    p = model::normalize_point(kind, m.faces[worst].pairing * p);
  }
  return false;
}

struct Attempt {
  DirichletDomain domain;
  bool bounded = false;
  std::vector<GroupElement> group;  // S3 only: the whole (finite) group
};

// One base point: conjugate, enumerate, cut. Throws GroupOrbit::Stabilised when the base
// point is fixed by some element.
Attempt attempt(GeometryKind kind, const std::vector<Mat4>& generators, const Vec3& base,
                const DirichletOptions& options) {
  Attempt a;
  a.domain.base_point = base;
  const Mat4 to_origin = model::translation(kind, -base), back = model::translation(kind, base);
  std::vector<Mat4> moved;
  for (const Mat4& g : generators) moved.push_back(to_origin * g * back);
  // Start from the shortest generator's reach; the first cells (too few elements: too large)
  // then set the radius and the slack.
  double step = INFINITY;
  for (const Mat4& g : moved) step = std::min(step, displacement(kind, g * model::origin()));

  // Enumerate (all of S3's finite group; a ball in E3 and H3) until the ball holds every
  // element whose bisector is within the cell's circumradius R.
  step = std::max(step, 1e-6);
  if (kind == GeometryKind::Hyperbolic && step > kHyperbolicPrecision) {
    char figures[96];
    std::snprintf(figures, sizeof figures, "%.6g, beyond distance %g", step, kHyperbolicPrecision);
    fail(std::string("the shortest generator (after shortening the set) moves the base point by ") +
         figures + ", within which double precision tells the elements of an H3 group apart");
  }
  double radius = kind == GeometryKind::Spherical ? 2 * std::numbers::pi : step;
  std::optional<GroupOrbit> orbit;
  Cell cell;
  std::optional<Manifold> cusped;  // this cell's manifold, built to check a cusped cell closed
  double cusped_error = 0;
  for (int growth = 0;; ++growth) {
    cusped.reset();
    // Words whose prefixes stray beyond the ball: half the circumradius of detour is allowed
    // (a wider margin costs e^(2 margin) elements in H3); validation catches a short count.
    const double slack = std::isfinite(cell.circumradius) ? cell.circumradius / 2 : step;
    const double orbit_limit = kind == GeometryKind::Hyperbolic
                                   ? std::min(radius + slack, kHyperbolicPrecision)
                                   : radius + slack;
    try {
      orbit.emplace(kind, moved, options.max_elements, orbit_limit);
    } catch (const GroupOrbit::TooLarge&) {
      // A cell still open after growing: a discrete group with an unbounded domain (two
      // translations in E3) runs into the cap as surely as a dense one does.
      if (growth > 0 && !cell.polyhedron.bounded)
        fail_unbounded(kind, "the cell was still open when the enumeration reached " +
                                 std::to_string(options.max_elements) + " elements");
      fail("the group enumeration exceeded " + std::to_string(options.max_elements) +
           " elements (within distance " + std::to_string(orbit_limit) +
           " of the base point): the group is not discrete, or its domain is huge");
    }
    cell = dirichlet_cell(kind, *orbit, options.tolerance);
    const double needed = 2 * cell.circumradius;
    bool closed = orbit->complete() || (cell.polyhedron.bounded && needed <= radius);
    if (closed && cell.ideal_vertices > 0) {  // cusps: closed once the pairings make the group
      try {
        const Manifold& m = cusped.emplace(
            manifold_of(kind, *orbit, cell, options.tolerance, cusped_error));
        closed = std::all_of(moved.begin(), moved.end(),
                             [&](const Mat4& g) { return generated_by_pairings(kind, m, g); });
      } catch (const SceneError&) {
        closed = false;  // a face without its partner yet: more elements
      }
    }
    if (closed) break;
    if (growth == kMaxGrowth) break;
    if (kind == GeometryKind::Hyperbolic && radius >= kHyperbolicReach) {
      if (!cell.polyhedron.bounded)
        fail_unbounded(kind, "the cell was still open at distance " +
                                 std::to_string(int(kHyperbolicReach)) + " from the base point");
      if (cell.ideal_vertices > 0)
        fail("the cell with " + std::to_string(cell.ideal_vertices) +
             " ideal vertices (cusps) found within distance " +
             std::to_string(int(kHyperbolicReach)) +
             " of the base point is not a fundamental domain: its face pairings do not "
             "generate the group, or do not close up around its edges");
      break;
    }
    radius = std::isfinite(needed) ? std::max(needed * 1.01, radius * 1.25) : radius * 2;
    if (kind == GeometryKind::Hyperbolic) radius = std::min(radius, kHyperbolicReach);
  }
  a.domain.elements = orbit->elements().size();
  a.domain.finite = orbit->complete();
  a.domain.product_drift = orbit->product_drift();
  if (kind == GeometryKind::Spherical && a.domain.finite) a.group = orbit->elements();
  a.bounded = cell.polyhedron.bounded && !cell.polyhedron.vertices.empty() &&
              (kind != GeometryKind::Spherical ||
               cell.circumradius <= kMaxSphericalCircumradius);
  if (!a.bounded) return a;
  if (cusped) {
    a.domain.manifold = std::move(*cusped);
    a.domain.isometry_error = cusped_error;
  } else {
    a.domain.manifold = manifold_of(kind, *orbit, cell, options.tolerance, a.domain.isometry_error);
  }
  a.domain.circumradius = cell.circumradius;
  a.domain.inradius = INFINITY;
  for (const Cut& c : cell.cuts)
    a.domain.inradius = std::min(a.domain.inradius, orbit->elements()[c.element].displacement / 2);
  a.domain.volume = domain_volume(kind, a.domain.manifold.domain);
  a.domain.cusps = static_cast<int>(cusps(kind, a.domain.manifold, options.tolerance).size());
  return a;
}

// Base points to try, in order: the requested one (or the origin), then fixed nudges off it
// in generic directions, scaled to the generators' reach (S3: up to a Clifford-torus point,
// where a lens space's orbit spreads over all of R4).
std::vector<Vec3> base_points(GeometryKind kind, const std::vector<Mat4>& generators,
                              const DirichletOptions& options) {
  const Vec3 start = options.base_point.value_or(Vec3{});
  double reach = INFINITY;
  for (const Mat4& g : generators)
    reach = std::min(reach, displacement(kind, g * model::origin()));
  const double scale = kind == GeometryKind::Spherical ? std::numbers::pi / 4
                                                       : std::max(reach, 1e-6) * 0.15;
  std::vector<Vec3> points{start, start + 0.5 * scale * normalize(Vec3{0.31, 0.17, 0.11})};
  for (const Vec3& d : {Vec3{1, 0, 0}, Vec3{0.6, 0.8, 0}, Vec3{0.2, -0.5, 0.84},
                        Vec3{-0.7, 0.1, 0.4}, Vec3{0, 0, 1}, Vec3{0.5, 0.5, 0.7071}})
    points.push_back(start + scale * normalize(d));
  return points;
}

// S3 groups whose domain no gnomonic chart holds: the domain cut into pieces (chart_atlas.h).
Attempt atlas(Attempt a, double tolerance) {
  constexpr auto kS3 = GeometryKind::Spherical;
  a.domain.manifold = chart_atlas_manifold(a.group, tolerance);
  a.domain.volume = 0;
  a.domain.circumradius = 0;
  for (const DomainPiece& p : a.domain.manifold.pieces) {
    a.domain.volume += domain_volume(kS3, p.polyhedron);
    const Mat4 to_model = model::inverse_isometry(kS3, p.chart_isometry);
    for (const Vec3& v : p.polyhedron.vertices)
      a.domain.circumradius =
          std::max(a.domain.circumradius, displacement(kS3, to_model * model::lift(kS3, v)));
    for (const PieceFace& f : p.faces)
      a.domain.isometry_error = std::max(a.domain.isometry_error, model::isometry_error(kS3, f.pairing));
  }
  a.domain.inradius = INFINITY;  // half the distance to the nearest image of the origin
  for (std::size_t i = 1; i < a.group.size(); ++i)
    a.domain.inradius = std::min(a.domain.inradius, a.group[i].displacement / 2);
  a.bounded = true;
  return a;
}

// The dimension of the span of E3 translations (Gram-Schmidt, relative to their lengths), or -1
// when some generator is not a translation. A group of translations is the lattice it spans:
// compact quotient only at rank 3, an answer that needs no enumeration (hundreds of
// collinear translations would otherwise fill the element cap first).
int translation_rank(GeometryKind kind, const std::vector<Mat4>& generators) {
  if (kind != GeometryKind::Euclidean) return -1;
  std::vector<Vec3> basis;
  for (const Mat4& g : generators) {
    Vec3 v = (g * model::origin()).xyz();
    const Mat4 t = model::translation(kind, v);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (std::abs(g.m[i][j] - t.m[i][j]) > 1e-9) return -1;
    const double size = length(v);
    for (const Vec3& b : basis) v = v - b * dot(v, b);
    if (length(v) > 1e-9 * std::max(1.0, size)) basis.push_back(v / length(v));
  }
  return int(basis.size());
}

}  // namespace

DirichletDomain dirichlet_domain(GeometryKind kind, const std::vector<Mat4>& generators,
                                 const DirichletOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (generators.empty()) fail("needs at least one generator");
  // Once, before the base points: the same group from fewer, shorter generators.
  const std::vector<Mat4> reduced = reduce_generators(kind, generators);
  if (reduced.empty()) fail("the generators are all the identity: the group is trivial");
  if (const int rank = translation_rank(kind, reduced); rank >= 0 && rank < 3)
    fail_unbounded(kind, std::string("they are translations spanning only a ") +
                             (rank == 1 ? "line" : "plane"));
  std::optional<Attempt> best, unbounded;
  int fixed = 0;
  for (const Vec3& base : base_points(kind, generators, options)) {
    Attempt a;
    try {
      a = attempt(kind, reduced, base, options);
    } catch (const GroupOrbit::Stabilised&) {
      ++fixed;
      continue;
    }
    if (!a.bounded) {
      if (!unbounded && !a.group.empty()) unbounded = std::move(a);
      continue;
    }
    const bool better = !best || a.domain.circumradius < best->domain.circumradius;
    if (better) best = std::move(a);
    // The origin (or the requested point) is kept unless the domain is awkward to chart.
    if (kind != GeometryKind::Spherical || best->domain.circumradius < 1.2) break;
  }
  if (!best && unbounded) best = atlas(std::move(*unbounded), options.tolerance);
  if (!best) {
    if (fixed == static_cast<int>(base_points(kind, generators, options).size()))
      fail("every base point tried is fixed by a group element: the group is not discrete");
    fail_unbounded(kind);
  }
  best->domain.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return std::move(best->domain);
}

}  // namespace geodesic
