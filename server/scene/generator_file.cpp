#include "scene/generator_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "geometry/moebius.h"
#include "scene/moebius_text.h"
#include "scene/preparation_budget.h"
#include "scene/scene.h"
#include "scene/text_chars.h"

namespace geodesic {
namespace {

// A matrix as read, with the line its first row came from.
struct RawMatrix {
  Mat4 m;
  int line = 0;
};

[[noreturn]] void fail(const std::string& source, std::size_t index, int line,
                       const std::string& reason) {
  throw SceneError(source + ": matrix " + std::to_string(index + 1) +
                   (line > 0 ? " (line " + std::to_string(line) + ")" : std::string()) + ": " +
                   reason);
}

// Parses one number token in full, or fails naming it.
double number(const std::string& token, const std::string& source, std::size_t index, int line) {
  char* end = nullptr;
  const double x = std::strtod(token.c_str(), &end);
  if (token.empty() || end != token.c_str() + token.size())
    fail(source, index, line, "\"" + token + "\" is not a number");
  if (!std::isfinite(x)) fail(source, index, line, "entry \"" + token + "\" is not finite");
  return x;
}

std::string_view without_bom(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  return text;
}

// The first comment line's text (at most 100 bytes), when comments open the text.
std::string first_comment(std::string_view text) {
  while (!text.empty()) {
    const std::string_view line = text.substr(0, text.find('\n'));
    text.remove_prefix(std::min(line.size() + 1, text.size()));
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) continue;
    if (line[first] != '#') return {};
    const std::size_t from = line.find_first_not_of("# \t\r", first);
    if (from == std::string_view::npos) continue;
    const std::size_t to = line.find_last_not_of(" \t\r");
    return std::string(line.substr(from, std::min<std::size_t>(to + 1 - from, 100)));
  }
  return {};
}

// The text with '#' comments blanked out, line breaks kept (for line numbers).
std::string without_comments(std::string_view text) {
  std::string out;
  bool comment = false;
  for (const char c : text) {
    if (c == '\n') comment = false;
    else if (c == '#') comment = true;
    out += comment ? ' ' : c;
  }
  return out;
}

// Curved Spaces: blocks of rows separated by blank (or comment-only) lines; a block of 4k rows
// is k matrices. Row-vector convention, so each matrix is transposed.
std::vector<RawMatrix> read_gen(std::string_view text, const std::string& source) {
  std::vector<RawMatrix> out;
  std::vector<std::vector<std::string>> rows;
  int first_line = 0, line_no = 0;
  auto flush = [&] {
    if (rows.size() % 4 != 0)
      fail(source, out.size() + rows.size() / 4, first_line + int(rows.size() / 4 * 4),
           "has " + std::to_string(rows.size() % 4) + " rows, not 4 (matrices are 4x4)");
    for (std::size_t k = 0; k < rows.size(); k += 4) {
      RawMatrix raw;
      raw.line = first_line + int(k);
      for (int r = 0; r < 4; ++r) {
        if (rows[k + r].size() != 4)
          fail(source, out.size(), raw.line + r,
               "row " + std::to_string(r + 1) + " has " + std::to_string(rows[k + r].size()) +
                   " entries, not 4");
        for (int c = 0; c < 4; ++c)
          raw.m.m[c][r] = number(rows[k + r][c], source, out.size(), raw.line + r);  // transpose
      }
      out.push_back(raw);
    }
    rows.clear();
  };
  std::istringstream in{std::string(text)};
  std::string line;
  while (std::getline(in, line)) {
    if (++line_no % 256 == 0) check_preparation_budget();
    std::istringstream fields(line);
    std::vector<std::string> row;
    for (std::string f; fields >> f;) row.push_back(f);
    if (row.empty()) {
      flush();
      continue;
    }
    if (rows.empty()) first_line = line_no;
    rows.push_back(std::move(row));
  }
  flush();
  return out;
}

// Each number in the text with its line: digits, a sign or '.' before digits, an exponent;
// digits inside a name (e.g. "O31") are not numbers.
std::vector<std::pair<std::string_view, int>> number_tokens(std::string_view text) {
  std::vector<std::pair<std::string_view, int>> out;
  int line_no = 1;
  for (std::size_t i = 0, steps = 1; i < text.size(); ++steps) {
    if (steps % 4096 == 0) check_preparation_budget();
    const char c = text[i];
    const bool starts_number =
        is_digit(c) || ((c == '-' || c == '+' || c == '.') && i + 1 < text.size() &&
                        (is_digit(text[i + 1]) || text[i + 1] == '.'));
    const bool in_name = i > 0 && is_alpha(text[i - 1]);
    if (c == '\n') ++line_no;
    if (!starts_number || in_name) {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) ||
                               text[j] == '.' ||
                               ((text[j] == '-' || text[j] == '+') &&
                                (text[j - 1] == 'e' || text[j - 1] == 'E'))))
      ++j;
    out.emplace_back(text.substr(i, j - i), line_no);
    i = j;
  }
  return out;
}

// Why the characters of a row (the text inside an innermost [...]) do not make entries, or
// "" when they do: a '.' with no digit beside it, a sign with no number after it, a '*' not
// between a number and an imaginary unit (`units`), or parentheses that do not pair up.
std::string row_structure_fault(std::string_view row, bool units) {
  auto next = [&](std::size_t k) {  // the first character after k that is not a space
    while (++k < row.size() && std::isspace(static_cast<unsigned char>(row[k]))) {}
    return k < row.size() ? row[k] : '\0';
  };
  auto unit = [&](char c) { return units && (c == 'I' || c == 'i' || c == 'j'); };
  int depth = 0;
  for (std::size_t k = 0; k < row.size(); ++k) {
    const char c = row[k];
    const char before = k > 0 ? row[k - 1] : '\0';
    if (c == '(') ++depth;
    if (c == ')' && --depth < 0) return "a \")\" closes no \"(\"";
    if (c == '.' && !is_digit(before) && !(k + 1 < row.size() && is_digit(row[k + 1])))
      return "a \".\" has no digit beside it";
    const bool exponent_sign = (before == 'e' || before == 'E') && k > 1 &&
                               (is_digit(row[k - 2]) || row[k - 2] == '.');
    if ((c == '+' || c == '-') && !exponent_sign) {
      const char n = next(k);
      if (!(is_digit(n) || n == '.' || n == '(' || unit(n)))
        return std::string("a \"") + c + "\" has no number after it";
    }
    if (c == '*' && !(is_digit(before) || before == '.')) return "a \"*\" follows no number";
    if (c == '*' && !unit(next(k))) return "a \"*\" is not followed by an imaginary unit";
  }
  return depth > 0 ? "a \"(\" is not closed" : "";
}

// The entries in text, as written, with their lines: with `units`, Moebius text's entries
// (numbers, imaginary units, "real + imaginary" pairs); otherwise its numbers.
std::vector<std::pair<std::string_view, int>> entries_in(std::string_view text, bool units) {
  return units ? moebius_entries(text) : number_tokens(text);
}

// Refuses anything inside a row (an innermost [...]) that is not part of an entry: a word
// other than an exponent or an imaginary unit (`units`: Moebius text only), a character
// other than digits, signs, '.', '*', separators (whitespace , ; ( )), or those characters
// out of place (row_structure_fault), or a row of other than `size` entries (a size x size
// matrix: 2 for Moebius text, 4 for O(3,1) rows). Words outside rows ("Matrix", "conj") stay
// separators, but an entry outside every row is refused: the readers take every entry in
// the text, so it would silently become part of a matrix.
void check_rows(std::string_view text, const std::string& source, bool units,
                std::size_t size) {
  std::size_t open = std::string_view::npos, rows = 0, outside = 0;
  int line = 1, open_line = 1, outside_line = 1;
  const auto check_outside = [&](std::size_t end) {
    const auto stray = entries_in(text.substr(outside, end - outside), units);
    if (!stray.empty())
      fail(source, rows / size, outside_line + stray[0].second - 1,
           "\"" + std::string(stray[0].first.substr(0, 40)) +
               "\" lies outside every row [...]: entries belong inside rows");
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (i % 4096 == 4095) check_preparation_budget();
    const char c = text[i];
    if (c == '\n') ++line;
    if (c == '[' || (c == ']' && open == std::string_view::npos)) {
      check_outside(i);
      outside = i + 1, outside_line = line;
    }
    if (c == '[') open = i, open_line = line;
    if (c != ']' || open == std::string_view::npos) continue;
    outside = i + 1, outside_line = line;
    const std::string_view row = text.substr(open + 1, i - open - 1);
    const std::string shown =
        "[" + std::string(row.substr(0, 60)) + (row.size() > 60 ? "..." : "") + "]";
    int at = open_line;
    for (std::size_t k = 0; k < row.size(); ++k) {
      const char r = row[k];
      if (r == '\n') ++at;
      const bool after_number = k > 0 && (is_digit(row[k - 1]) || row[k - 1] == '.');
      const bool exponent = (r == 'e' || r == 'E') && after_number && k + 1 < row.size() &&
                            (is_digit(row[k + 1]) || row[k + 1] == '+' || row[k + 1] == '-');
      std::size_t end = k + 1;
      if (is_alpha(r) && !exponent)
        while (end < row.size() && (is_alpha(row[end]) || is_digit(row[end]))) ++end;
      const std::string_view word = row.substr(k, end - k);
      const bool unit = units && (word == "I" || word == "i" || word == "j");
      const bool allowed = is_alpha(r) ? exponent || unit
                                       : is_digit(r) || std::isspace(static_cast<unsigned char>(r)) ||
                                             std::string_view("+-.*,;()").find(r) != std::string_view::npos;
      if (!allowed)
        fail(source, rows / size, at,
             "\"" + std::string(word.substr(0, 40)) + "\" inside " + shown +
                 " is not part of a number");
      k = end - 1;
    }
    if (const std::string fault = row_structure_fault(row, units); !fault.empty())
      fail(source, rows / size, open_line, fault + " inside " + shown);
    const std::size_t entries = entries_in(row, units).size();
    if (entries != size)
      fail(source, rows / size, open_line,
           "row " + std::to_string(rows % size + 1) + ", " + shown + ", has " +
               std::to_string(entries) + (entries == 1 ? " entry" : " entries") + ", not " +
               std::to_string(size));
    open = std::string_view::npos;
    ++rows;
  }
  check_outside(text.size());  // also after a "[" that no "]" closed
}

// SnapPy: every number in the text, 16 to a matrix, row by row, time coordinate first.
std::vector<RawMatrix> read_snappy(std::string_view text, const std::string& source) {
  std::vector<double> values;
  std::vector<int> lines;
  for (const auto& [token, line] : number_tokens(text)) {
    values.push_back(number(std::string(token), source, values.size() / 16, line));
    lines.push_back(line);
  }
  if (values.size() % 16 != 0)
    fail(source, values.size() / 16, lines.back(),
         "has " + std::to_string(values.size() % 16) + " entries, not 16 (matrices are 4x4)");
  std::vector<RawMatrix> out;
  const int to_ours[4] = {3, 0, 1, 2};  // SnapPy index -> ours: time moves to w
  for (std::size_t k = 0; k < values.size(); k += 16) {
    RawMatrix raw;
    raw.line = lines[k];
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) raw.m.m[to_ours[r]][to_ours[c]] = values[k + 4 * r + c];
    out.push_back(raw);
  }
  return out;
}

// The models whose isometry `g` is, as a bit set over GeometryKind.
unsigned models_of(const Mat4& g) {
  unsigned bits = 0;
  const double size = std::max(1.0, g.max_abs());
  for (const GeometryKind k :
       {GeometryKind::Euclidean, GeometryKind::Hyperbolic, GeometryKind::Spherical}) {
    const double bound = kGeneratorTolerance * (k == GeometryKind::Euclidean ? 1 : size * size);
    if (!(model::isometry_error(k, g) <= bound)) continue;
    if (k == GeometryKind::Hyperbolic && g.m[3][3] <= 0) continue;  // swaps the sheets
    bits |= 1u << static_cast<unsigned>(k);
  }
  return bits;
}

std::string names_of(unsigned bits) {
  std::string s;
  for (const GeometryKind k :
       {GeometryKind::Euclidean, GeometryKind::Hyperbolic, GeometryKind::Spherical})
    if (bits & (1u << static_cast<unsigned>(k))) s += std::string(s.empty() ? "" : ", ") + geometry_name(k);
  return s;
}

// The common geometry of the matrices.
GeneratorSet classify(const std::vector<RawMatrix>& raw, const std::string& source) {
  if (raw.empty())
    throw SceneError(source + ": no matrices (a quotient needs at least one generator)");
  unsigned common = 7;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (i % 256 == 255) check_preparation_budget();
    const unsigned mine = models_of(raw[i].m);
    if (!mine)
      fail(source, i, raw[i].line,
           "not an isometry of euclidean, hyperbolic or spherical space (to relative " +
               std::to_string(kGeneratorTolerance).substr(0, 8) + ")");
    if (!(common & mine))
      fail(source, i, raw[i].line,
           "is an isometry of " + names_of(mine) + " space only, but the matrices before it are "
           "not (" + names_of(common) + ")");
    common &= mine;
  }
  if (common & (common - 1))
    throw SceneError(source + ": the matrices fix the origin, so they are isometries of " +
                     names_of(common) + " space alike: the geometry is ambiguous");
  GeneratorSet set;
  set.kind = static_cast<GeometryKind>(__builtin_ctz(common));
  for (const RawMatrix& r : raw) set.generators.push_back(r.m);
  return set;
}

}  // namespace

GeneratorSet parse_generators(std::string_view text, const std::string& source) {
  const std::string bare = without_comments(without_bom(text));
  std::vector<RawMatrix> raw;
  if (looks_like_moebius(bare)) {
    check_rows(bare, source, true, 2);
    for (const MoebiusText& m : read_moebius(bare, source))
      raw.push_back({moebius_isometry(m.t), m.line});
  } else {
    const bool snappy = bare.find('[') != std::string::npos;
    if (snappy) check_rows(bare, source, false, 4);
    raw = snappy ? read_snappy(bare, source) : read_gen(bare, source);
  }
  GeneratorSet set = classify(raw, source);
  set.title = first_comment(without_bom(text));
  return set;
}

GeneratorSet generator_set(const std::vector<Mat4>& generators, const std::string& source) {
  std::vector<RawMatrix> raw;
  for (const Mat4& g : generators) raw.push_back({g, 0});
  return classify(raw, source);
}

GeneratorSet load_generator_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error) || !in)
    throw SceneError(path.string() + ": cannot open file (missing or not a regular file)");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_generators(text.str(), path.string());
}

std::string format_gen(const std::vector<Mat4>& generators, const std::string& header) {
  std::string out;
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);) out += (line.empty() ? "#" : "#\t" + line) + "\n";
  for (const Mat4& g : generators) {
    out += "\n";
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        char buf[40];
        const double x = g.m[c][r] == 0 ? 0.0 : g.m[c][r];  // no "-0"
        std::snprintf(buf, sizeof buf, "%s%.20f", x < 0 ? "" : " ", x);
        out += std::string(c ? "  " : " ") + buf;
      }
      out += "\n";
    }
  }
  return out;
}

}  // namespace geodesic
