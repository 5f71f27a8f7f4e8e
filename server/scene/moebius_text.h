// Moebius generators as text: 2x2 complex matrices in brackets, the form SnapPy prints for
// M.fundamental_group().SL2C(word) and the literature writes cusped groups in.
//
//   [[1, 1], [0, 1]]
//   [[1, 0], [0.5 - 0.8660254037844386*I, 1]]
//   conj [[0.5 + 0.8660254037844386*I, 1], [1, 0]]
//
// Entries are real numbers, imaginary ones (a suffix i, j, I, *i, *j or *I; a bare unit), or a
// real and an imaginary one joined by + or - with spaces on both sides of the sign or on
// neither ("0.5 - 0.87*I", "0.5-0.87i"; "0.5 -0.87i" is two entries). Commas, parentheses and
// other words are separators between rows; inside a row's brackets anything that is not part
// of an entry is refused by parse_generators (scene/generator_file.h). Four entries make a
// matrix, row by row; the word `conj` before a matrix makes it orientation-reversing
// (z -> (a conj z + b) / (c conj z + d)).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geometry/moebius.h"

namespace geodesic {

struct MoebiusText {
  Moebius t;
  int line = 0;  // of its first entry
};

// True when the first innermost [...] of the text holds two entries (a 2x2 matrix's row):
// Moebius text rather than SnapPy's O(3,1) rows of four.
bool looks_like_moebius(std::string_view text);

// Every entry in the text, as written, with its line (1 for the text's first).
std::vector<std::pair<std::string_view, int>> moebius_entries(std::string_view text);

// Throws SceneError "<source>: matrix <i> (line <l>): <reason>" for an entry that is not a
// number, a count that is not a multiple of 4, or a determinant of zero.
std::vector<MoebiusText> read_moebius(std::string_view text, const std::string& source);

}  // namespace geodesic
