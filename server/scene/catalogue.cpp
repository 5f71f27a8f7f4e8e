#include "scene/catalogue.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>

#include "geometry/moebius.h"
#include "scene/coxeter_orthoscheme.h"
#include "scene/dirichlet_domain.h"
#include "scene/generator_file.h"
#include "scene/manifold.h"
#include "scene/scene.h"

namespace geodesic {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr auto kE3 = GeometryKind::Euclidean;
constexpr auto kH3 = GeometryKind::Hyperbolic;
constexpr auto kS3 = GeometryKind::Spherical;

// Affine maps of E3: x -> linear(x) + t.
Mat4 affine(const Mat4& linear, const Vec3& t) {
  Mat4 g = linear;
  g.m[0][3] = t.x;
  g.m[1][3] = t.y;
  g.m[2][3] = t.z;
  return g;
}
Mat4 shift(const Vec3& t) { return affine(Mat4::identity(), t); }
Mat4 diagonal(double x, double y, double z) {
  Mat4 g = Mat4::identity();
  g.m[0][0] = x;
  g.m[1][1] = y;
  g.m[2][2] = z;
  return g;
}
// Screw motion: turn by `angle` about the z axis, then move `pitch` along it.
Mat4 screw(double angle, double pitch) {
  return affine(model::rotation({0, 0, 1}, angle), {0, 0, pitch});
}

const Vec3 kHexA{2, 0, 0}, kHexB{1, std::sqrt(3.0), 0};  // hexagonal lattice, side 2

// A flat space of `holonomy` order whose translation subgroup has covolume `lattice_volume`.
CatalogueEntry flat(std::string name, std::string title, std::string derivation,
                    std::vector<Mat4> generators, double lattice_volume, int holonomy) {
  return {std::move(name), std::move(title), kE3, std::move(derivation), std::move(generators),
          std::nullopt, lattice_volume / holonomy, false};
}

CatalogueEntry spherical(std::string name, std::string title, std::string derivation,
                         std::vector<Mat4> generators, int order) {
  return {std::move(name), std::move(title), kS3, std::move(derivation), std::move(generators),
          order, 2 * kPi * kPi / order, false};
}

CatalogueEntry lens(int p, int q) {
  const std::string pq = std::to_string(p) + "," + std::to_string(q);
  return spherical("lens-" + std::to_string(p) + "-" + std::to_string(q), "Lens space L(" + pq + ")",
                   "one generator: the xy plane turned by 2 pi / " + std::to_string(p) +
                       " and the zw plane by 2 pi " + std::to_string(q) + " / " +
                       std::to_string(p) + " (lens_space_generators)",
                   lens_space_generators(p, q), p);
}

// Binary dihedral group D*_n of order 4n: <e^(i pi / n), j> acting by left multiplication.
CatalogueEntry binary_dihedral(int n) {
  return spherical("binary-dihedral-" + std::to_string(n),
                   "Prism space S3 / D*" + std::to_string(n) + " (binary dihedral, order " +
                       std::to_string(4 * n) + ")",
                   "left multiplication by the unit quaternions cos(pi/" + std::to_string(n) +
                       ") + sin(pi/" + std::to_string(n) + ") i and j",
                   {left_multiplication(std::cos(kPi / n), std::sin(kPi / n), 0, 0),
                    left_multiplication(0, 0, 1, 0)},
                   4 * n);
}

CatalogueEntry mirrored_lens(int n) {
  return {"mirrored-lens-" + std::to_string(n),
          "Mirrored lens, dihedral angle 2 pi / " + std::to_string(n) + " (orbifold)", kS3,
          "reflections in the two great spheres through the xy great circle at angles +-pi / " +
              std::to_string(n) + " from the w axis (mirrored_lens_generators)",
          mirrored_lens_generators(n), n, 2 * kPi * kPi / n, true};
}

std::vector<CatalogueEntry> build() {
  const double s3 = std::sqrt(3.0), hex_area = 2 * s3;
  std::vector<CatalogueEntry> c;
  // Flat: the translation lattice's covolume over the holonomy's order (the quotient's volume).
  c.push_back(flat("3-torus", "Cubic 3-torus", "translations by 2 along x, y and z",
                   {shift({2, 0, 0}), shift({0, 2, 0}), shift({0, 0, 2})}, 8, 1));
  c.push_back(flat("hexagonal-torus", "Hexagonal 3-torus",
                   "translations by (2, 0, 0), (1, sqrt 3, 0) and (0, 0, 2)",
                   {shift(kHexA), shift(kHexB), shift({0, 0, 2})}, hex_area * 2, 1));
  c.push_back(flat("half-turn", "Half-turn space (dicosm)",
                   "translations by 2 along x and y; a half-turn screw about z with pitch 2",
                   {shift({2, 0, 0}), shift({0, 2, 0}), screw(kPi, 2)}, 2 * 2 * 4, 2));
  c.push_back(flat("quarter-turn", "Quarter-turn space (tetracosm)",
                   "translations by 2 along x and y; a quarter-turn screw about z with pitch 2",
                   {shift({2, 0, 0}), shift({0, 2, 0}), screw(kPi / 2, 2)}, 2 * 2 * 8, 4));
  c.push_back(flat("third-turn", "Third-turn space (tricosm)",
                   "hexagonal translations (2, 0, 0), (1, sqrt 3, 0); a third-turn screw about z "
                   "with pitch 2",
                   {shift(kHexA), shift(kHexB), screw(2 * kPi / 3, 2)}, hex_area * 6, 3));
  c.push_back(flat("sixth-turn", "Sixth-turn space (hexacosm)",
                   "hexagonal translations (2, 0, 0), (1, sqrt 3, 0); a sixth-turn screw about z "
                   "with pitch 2",
                   {shift(kHexA), shift(kHexB), screw(kPi / 3, 2)}, hex_area * 12, 6));
  c.push_back(flat("hantzsche-wendt", "Hantzsche-Wendt space (didicosm)",
                   "three half-turn screws about the x, y and z axes shifted by 1: "
                   "(x+1, 1-y, -z), (-x, y+1, 1-z), (1-x, -y, z+1); lattice 2Z^3",
                   {affine(diagonal(1, -1, -1), {1, 1, 0}), affine(diagonal(-1, 1, -1), {0, 1, 1}),
                    affine(diagonal(-1, -1, 1), {1, 0, 1})},
                   8, 4));
  c.push_back(flat("first-amphicosm", "First amphicosm (Klein bottle times circle)",
                   "the glide reflection (x+1, -y, z) and translations by 2 along y and z",
                   {affine(diagonal(1, -1, 1), {1, 0, 0}), shift({0, 2, 0}), shift({0, 0, 2})},
                   8, 2));
  c.push_back(flat("second-amphicosm", "Second amphicosm",
                   "the glide reflection (x+1, -y, z) and translations by (0, 2, 0) and "
                   "(0, 1, 2): a lattice the reflection preserves without splitting",
                   {affine(diagonal(1, -1, 1), {1, 0, 0}), shift({0, 2, 0}), shift({0, 1, 2})},
                   8, 2));

  // Spherical: finite subgroups of the unit quaternions acting by left multiplication.
  for (int n = 2; n <= 6; ++n) c.push_back(binary_dihedral(n));
  const Mat4 tetra = left_multiplication(0.5, 0.5, 0.5, 0.5);
  c.push_back(spherical("binary-tetrahedral", "Octahedral space S3 / T* (binary tetrahedral)",
                        "left multiplication by i and (1 + i + j + k) / 2",
                        {left_multiplication(0, 1, 0, 0), tetra}, 24));
  c.push_back(spherical("binary-octahedral",
                        "Truncated-cube space S3 / O* (binary octahedral)",
                        "left multiplication by (1 + i) / sqrt 2 and (1 + i + j + k) / 2",
                        {left_multiplication(std::sqrt(0.5), std::sqrt(0.5), 0, 0), tetra}, 48));
  constexpr double phi = std::numbers::phi;
  c.push_back(spherical("binary-icosahedral",
                        "Poincare dodecahedral space S3 / I* (binary icosahedral)",
                        "left multiplication by (1 + i + j + k) / 2 and (phi + i / phi + j) / 2",
                        {tetra, left_multiplication(phi / 2, 0.5 / phi, 0.5, 0)}, 120));
  // L(p, 1) and its mirror image L(p, p - 1) preserve a great circle, like RP3 below.
  for (const auto& [p, q] : {std::pair{3, 1}, {5, 1}, {5, 2}, {6, 5}, {7, 2}, {7, 3}, {8, 3},
                             {9, 2}, {11, 3}, {12, 5}})
    c.push_back(lens(p, q));
  // -I preserves every great circle: the domain is cut into pieces (chart_atlas.h).
  // Mirrors through one great circle: their lune, too, is charted in pieces.
  for (int n : {4, 6}) c.push_back(mirrored_lens(n));
  c.push_back(spherical("projective-space", "Projective 3-space RP3 = L(2,1)",
                        "the antipodal map -I", {left_multiplication(-1, 0, 0, 0)}, 2));

  // Hyperbolic: from the bundled dodecahedra (scene/manifold.h), whose pairings are closed
  // forms. Volumes: Seifert-Weber 11.199064740, right-angled dodecahedron 4.306207601
  // (Weeks, SnapPea census; Vesnin).
  std::vector<Mat4> sw;
  const Manifold seifert_weber = make_seifert_weber_space();
  for (std::size_t f = 0; f < seifert_weber.faces.size(); f += 2)
    sw.push_back(seifert_weber.faces[f].pairing);
  c.push_back({"seifert-weber", "Seifert-Weber dodecahedral space", kH3,
               "opposite faces of the regular dodecahedron with 72-degree dihedral angles glued "
               "by 3/10-turn screws (one generator per face pair, make_seifert_weber_space)",
               sw, std::nullopt, 11.199064740, false});
  std::vector<Mat4> mirrors;
  for (const DomainFace& f : make_mirrored_dodecahedron().faces) mirrors.push_back(f.pairing);
  c.push_back({"mirrored-dodecahedron", "Mirrored right-angled dodecahedron (orbifold)", kH3,
               "the reflections in the 12 faces of the regular dodecahedron with right dihedral "
               "angles",
               mirrors, std::nullopt, 4.306207601, true});
  // Kaleidoscopes: the compact Coxeter orthoschemes, volumes by Lobachevsky's formula (120 of
  // [5,3,4] make the right-angled dodecahedron, 120 of [5,3,5] the Seifert-Weber one).
  for (const auto& [p, q, r] : {std::array{3, 5, 3}, {5, 3, 4}, {5, 3, 5}}) {
    const std::string diagram = std::to_string(p) + "," + std::to_string(q) + "," + std::to_string(r);
    c.push_back({"coxeter-" + std::to_string(p) + "-" + std::to_string(q) + "-" + std::to_string(r),
                 "Coxeter orthoscheme [" + diagram + "] (orbifold)", kH3,
                 "reflections in the faces of the tetrahedron with dihedral angles pi/" +
                     std::to_string(p) + ", pi/" + std::to_string(q) + ", pi/" + std::to_string(r) +
                     " along a path of edges and pi/2 elsewhere: unit normals with the diagram's "
                     "Gram matrix (coxeter_orthoscheme_generators)",
                 coxeter_orthoscheme_generators(p, q, r), std::nullopt, orthoscheme_volume(p, q, r),
                 true});
  }
  // Cusped: finite volume, not compact (ideal vertices in the Dirichlet domain). Moebius
  // generators (geometry/moebius.h) in closed form; volumes from the SnapPea census.
  const Complex omega(-0.5, std::sqrt(3.0) / 2);  // a primitive cube root of unity
  auto moebius = [](Complex a, Complex b, Complex cc, Complex d, bool reverses = false) {
    return moebius_isometry({{a, b, cc, d}, reverses});
  };
  c.push_back({"figure-eight", "Figure-eight knot complement (m004)", kH3,
               "Riley's parabolic representation: z -> z + 1 and z -> z / (1 - omega z), the "
               "Moebius matrices [[1, 1], [0, 1]] and [[1, 0], [-omega, 1]] with omega = "
               "(-1 + sqrt -3) / 2",
               {moebius(1, 1, 0, 1), moebius(1, 0, -omega, 1)}, std::nullopt, 2.029883212819307,
               false});
  c.push_back({"figure-eight-sister", "Figure-eight knot's sister (m003)", kH3,
               "face pairings of two regular ideal tetrahedra (H1 = Z + Z/5, which tells it from "
               "m004): the Moebius matrices [[0, 1], [-1, 1 + omega]] and [[-1 - omega, -1 - "
               "omega], [1 - omega, 1]], relator y^-1 x^2 y^-3 x^2 y^-1 x",
               {moebius(0, 1, -1, 1.0 + omega), moebius(-1.0 - omega, -1.0 - omega, 1.0 - omega, 1)},
               std::nullopt, 2.029883212819307, false});
  c.push_back({"gieseking", "Gieseking manifold (non-orientable)", kH3,
               "one regular ideal tetrahedron (inf, 0, 1, zeta = 1 + omega), faces (0,1,2) -> "
               "(3,1,0) and (0,2,3) -> (3,2,1) glued by the orientation-reversing z -> (a conj z "
               "+ b) / (c conj z + d) of [[-omega, 0], [-1 - omega, 1 + omega]] and [[-omega, 1 + "
               "omega], [-1 - omega, 2 + omega]], relator a^2 b^2 = b a",
               {moebius(-omega, 0, -1.0 - omega, 1.0 + omega, true),
                moebius(-omega, 1.0 + omega, -1.0 - omega, 2.0 + omega, true)},
               std::nullopt, 1.0149416064096536, false});
  c.push_back({"whitehead-link", "Whitehead link complement (m129)", kH3,
               "two parabolic meridians of the 2-bridge link 8/3: the Moebius matrices [[1, 1], "
               "[0, 1]] and [[1, 0], [-1 + i, 1]], relator a w = w a with w = b a b^-1 a^-1 "
               "b^-1 a b",
               {moebius(1, 1, 0, 1), moebius(1, 0, Complex(-1, 1), 1)}, std::nullopt,
               3.663862376708876, false});
  return c;
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

std::string domain_shape(const DirichletDomain& d) {
  const Manifold& m = d.manifold;
  if (m.pieces.empty()) {
    std::string s = std::to_string(m.faces.size()) + " faces, " +
                    std::to_string(m.domain.vertices.size()) + " vertices";
    if (d.cusps == 0) return s;
    int ideal = 0;
    for (const Vec3& v : m.domain.vertices) ideal += ideal_vertex(GeometryKind::Hyperbolic, v);
    return s + " (" + std::to_string(ideal) + " ideal); " + std::to_string(d.cusps) +
           (d.cusps == 1 ? " cusp" : " cusps");
  }
  std::size_t faces = 0;
  for (const DomainPiece& p : m.pieces) faces += p.faces.size();
  return std::to_string(m.pieces.size()) + " pieces, " + std::to_string(faces) + " faces";
}

std::string facts(const CatalogueEntry& e) {
  std::string s = std::string("geometry: ") + geometry_name(e.kind);
  if (e.group_order) s += "; group order " + std::to_string(*e.group_order);
  s += "; volume " + number(e.volume);
  if (e.orbifold) s += "; an orbifold (the group has fixed points)";
  return s;
}

}  // namespace

Mat4 left_multiplication(double a, double b, double c, double d) {
  // Columns: q times the basis quaternions i, j, k, 1 (our x, y, z, w).
  const double q[4][4] = {{-b, a, d, -c}, {-c, -d, a, b}, {-d, c, -b, a}, {a, b, c, d}};
  Mat4 g;
  for (int col = 0; col < 4; ++col) {
    const double* r = q[col];  // (real, i, j, k) of the product
    g.m[0][col] = r[1];
    g.m[1][col] = r[2];
    g.m[2][col] = r[3];
    g.m[3][col] = r[0];
  }
  return g;
}

std::vector<Mat4> lens_space_generators(int p, int q) {
  if (p < 2) throw SceneError("lens space L(p, q): p must be at least 2, not " + std::to_string(p));
  if (std::gcd(p, q) != 1)
    throw SceneError("lens space L(" + std::to_string(p) + ", " + std::to_string(q) +
                     "): p and q must be coprime (gcd " + std::to_string(std::gcd(p, q)) +
                     "), or the group does not act freely");
  Mat4 g = model::rotation({0, 0, 1}, 2 * kPi / p);  // the xy plane
  const double a = 2 * kPi * q / p;
  g.m[2][2] = std::cos(a);
  g.m[2][3] = -std::sin(a);
  g.m[3][2] = std::sin(a);
  g.m[3][3] = std::cos(a);
  return {g};
}

std::vector<Mat4> mirrored_lens_generators(int n) {
  if (n < 4 || n % 2)
    throw SceneError("mirrored lens: n must be even and at least 4 (the mirrors meet at 2 pi / n), not " +
                     std::to_string(n));
  auto mirror = [](double angle) {  // through the xy plane and the direction w cos + z sin
    const double u[2] = {std::cos(angle), -std::sin(angle)};  // its unit normal in (z, w)
    Mat4 g = Mat4::identity();
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) g.m[2 + r][2 + c] -= 2 * u[r] * u[c];
    return g;
  };
  return {mirror(kPi / n), mirror(-kPi / n)};
}

const std::vector<CatalogueEntry>& catalogue() {
  static const std::vector<CatalogueEntry> entries = build();
  return entries;
}

const CatalogueEntry* find_catalogue_entry(const std::string& name) {
  for (const CatalogueEntry& e : catalogue())
    if (e.name == name) return &e;
  return nullptr;
}

std::string catalogue_gen_text(const CatalogueEntry& e) {
  return format_gen(e.generators, e.title + "\n\n" + facts(e) + "\nmatrices: " + e.derivation +
                                      "\nwritten by `geodesic catalogue` (server/scene/catalogue.cpp)");
}

std::string catalogue_readme() {
  std::string s =
      "# The manifold catalogue\n\n"
      "Generated by `geodesic catalogue` from the closed forms in `server/scene/catalogue.cpp`;\n"
      "do not edit by hand (the unit tests compare these files with the generator's output).\n"
      "Each `<name>.gen` lists generators of the group Gamma in Curved Spaces' format (4x4\n"
      "matrices acting on row vectors, w last, 20 decimals); `scenes/catalogue/<name>.json`\n"
      "renders the space around its Dirichlet domain (`geodesic render scenes/catalogue/<name>.json`).\n"
      "Volumes: flat spaces, the translation lattice's covolume over the holonomy's order;\n"
      "spherical ones, 2 pi^2 / |Gamma|; hyperbolic ones, published values (the tests compare\n"
      "all of them with the volume of the computed Dirichlet domain).\n\n"
      "Projective space, L(p, 1), its mirror image L(p, p - 1) and the mirrored lenses preserve\n"
      "a great circle, so no fundamental domain fits one gnomonic chart: their Dirichlet domains\n"
      "are cut into pieces charted apart (server/scene/chart_atlas.h). A lune is cut like an\n"
      "orange into tetrahedra (p of them for L(p, 1), 4 for a mirrored lens), projective space\n"
      "by Voronoi cells; past eight, the renderer's cells share ray-mask bits and filter\n"
      "candidates by cell (docs/pipelines.md).\n\n"
      "The figure-eight knot complement, its sister, the Gieseking manifold and the Whitehead\n"
      "link complement are cusped: finite volume, not compact; their Dirichlet domains have\n"
      "ideal vertices on the sphere at infinity (one cusp each, two for the link), cut off in\n"
      "their scenes by horospheres. Any cusped manifold comes in from\n"
      "SnapPy as the Moebius matrices it prints for `G.SL2C(g)` (G = M.fundamental_group(), g\n"
      "over G.generators()) saved as a generator file (docs/scene-format.md, Cusped hyperbolic\n"
      "spaces).\n\n"
      "| name | geometry | order | volume | Dirichlet domain | generators |\n"
      "|---|---|---|---|---|---|\n";
  for (const CatalogueEntry& e : catalogue()) {
    const DirichletDomain d = dirichlet_domain(e.kind, e.generators);
    s += "| `" + e.name + "` " + e.title + " | " + geometry_name(e.kind) + " | " +
         (e.group_order ? std::to_string(*e.group_order) : "infinite") + " | " +
         number(e.volume) + " | " + domain_shape(d) + " | " + e.derivation + " |\n";
  }
  return s;
}

}  // namespace geodesic
