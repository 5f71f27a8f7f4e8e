// The classic catalogue of closed 3-manifolds (and some mirrored orbifolds) as generators of
// Gamma, each built from its closed form here: flat spaces from screw motions and glide
// reflections, spherical spaces from unit quaternions, lens rotations and mirrors, hyperbolic
// ones from the regular dodecahedra of scene/manifold.h and the Coxeter orthoschemes.
// `geodesic catalogue` writes them as catalogue/<name>.gen (with catalogue/README.md and a
// default scene per entry in scenes/catalogue/); the tests hold the committed files to this
// code.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/model.h"
#include "geometry/vec.h"

namespace geodesic {

struct CatalogueEntry {
  std::string name;        // file stem, e.g. "quarter-turn"
  std::string title;       // e.g. "Quarter-turn space"
  GeometryKind kind;
  std::string derivation;  // how the matrices follow from the closed form
  std::vector<Mat4> generators;
  std::optional<int> group_order;  // S3: |Gamma|
  double volume = 0;               // expected volume of the quotient
  bool orbifold = false;           // has mirrors or cone edges (Gamma does not act freely)
};

const std::vector<CatalogueEntry>& catalogue();
// nullptr when there is no entry of that name.
const CatalogueEntry* find_catalogue_entry(const std::string& name);

// The lens space L(p, q) = S3 / <g>, g turning the xy plane by 2 pi / p and the zw plane by
// 2 pi q / p. Throws SceneError unless p >= 2 and gcd(p, q) = 1.
std::vector<Mat4> lens_space_generators(int p, int q);

// The mirrored lens of dihedral angle 2 pi / n (an orbifold): reflections in the two great
// spheres through the xy great circle at angles +-pi / n from the w axis, generating the
// dihedral group of order n. Throws SceneError unless n is even and at least 4.
std::vector<Mat4> mirrored_lens_generators(int n);

// Unit quaternion a + b i + c j + d k as the S3 isometry x -> q x (x = w + x i + y j + z k).
Mat4 left_multiplication(double a, double b, double c, double d);

// The .gen text of an entry (title, geometry, order or volume and derivation as comments).
std::string catalogue_gen_text(const CatalogueEntry& entry);
// catalogue/README.md: one section per entry.
std::string catalogue_readme();

}  // namespace geodesic
