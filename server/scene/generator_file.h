// Generators of a group Gamma of isometries, as text: Jeff Weeks' Curved Spaces `.gen` files,
// the O(3,1) matrices SnapPy's DirichletDomain.pairing_matrices() prints, and the PSL(2, C)
// matrices it prints for M.fundamental_group().SL2C(word). All become 4x4 matrices in our convention (acting on column vectors, w the 4th coordinate), and the
// geometry follows from which model's form the matrices preserve.
//
//   .gen     4x4 blocks separated by blank lines, '#' comments, optional UTF-8 BOM; the
//            matrices act on ROW vectors (translation in the bottom row), so we transpose.
//   SnapPy   nested lists or Matrix([...]) rows, time coordinate FIRST (-x0^2 + x1^2 + ...),
//            acting on column vectors: we move the time coordinate last.
//   Moebius  2x2 complex matrices [[a, b], [c, d]] (scene/moebius_text.h), recognised by rows
//            of two entries; H3 isometries by geometry/moebius.h.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/model.h"
#include "geometry/vec.h"

namespace geodesic {

struct GeneratorSet {
  GeometryKind kind = GeometryKind::Euclidean;
  std::vector<Mat4> generators;  // column convention
  // The text's first comment line, which names the space in Curved Spaces' files and the
  // catalogue's ("#\tMirrored Lens with dihedral angle 2pi/6"); empty when the text does not
  // open with one.
  std::string title;
};

// Relative isometry tolerance for matrices read from text (entries carry 6 to 20 digits).
inline constexpr double kGeneratorTolerance = 1e-6;

// Parses any format (Moebius when the first [...] row holds two entries, else SnapPy's O(3,1)
// when the text contains '['). `source` names the text in errors, which throw SceneError as
// "<source>: matrix <i> (line <l>): <reason>": not 4x4, not a number, NaN or infinite, a word
// or character inside a row's [...] that is not part of an entry, or an entry outside every
// row (junk is refused by name here, not left to the group's enumeration), not an isometry of any model, or geometries
// that differ between matrices. A text without matrices is an error too (the whole space
// needs none).
GeneratorSet parse_generators(std::string_view text, const std::string& source);
// The same checks for matrices already in our convention (errors name no line).
GeneratorSet generator_set(const std::vector<Mat4>& generators, const std::string& source);
// Reads and parses a file; the error names the path.
GeneratorSet load_generator_file(const std::filesystem::path& path);

// The .gen text of `generators` (transposed to row vectors, 20 significant digits), after
// `header` written as '#' comment lines.
std::string format_gen(const std::vector<Mat4>& generators, const std::string& header);

}  // namespace geodesic
