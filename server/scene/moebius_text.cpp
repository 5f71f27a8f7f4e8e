#include "scene/moebius_text.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "scene/preparation_budget.h"
#include "scene/scene.h"
#include "scene/text_chars.h"

namespace geodesic {
namespace {

// One scanned item: an entry (real or imaginary term), a bracket, or the word conj.
struct Token {
  enum Kind { Term, Open, Close, Conj } kind;
  Complex value;
  bool imaginary = false;      // a term with an imaginary unit
  bool explicit_sign = false;  // a term written with a leading + or -
  bool space_before = false;   // whitespace between the sign and the previous item
  bool space_after_sign = false;
  int line = 0;
  std::string bad;  // a number that is not one, or not finite
  std::size_t begin = 0, end = 0;  // a term's span in the text
};

class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  std::vector<Token> tokens() {
    std::vector<Token> out;
    bool space = false;
    for (unsigned steps = 1; i_ < text_.size(); ++steps) {
      if (steps % 4096 == 0) check_preparation_budget();
      const char c = text_[i_];
      if (c == '\n') ++line_;
      if (c == '[' || c == ']') {
        out.push_back({c == '[' ? Token::Open : Token::Close, {}, false, false, space, false, line_, {}});
        ++i_;
        space = false;
        continue;
      }
      if (is_alpha(c)) {
        std::size_t j = i_;
        while (j < text_.size() && (is_alpha(text_[j]) || is_digit(text_[j]))) ++j;
        const std::string_view word = text_.substr(i_, j - i_);
        if (word == "conj") out.push_back({Token::Conj, {}, false, false, space, false, line_, {}});
        else if (word == "I" || word == "i" || word == "j")
          out.push_back({Token::Term, Complex(0, 1), true, false, space, false, line_, {}, i_, j});
        i_ = j;
        space = false;
        continue;
      }
      if (const auto t = term(space)) {
        out.push_back(*t);
        space = false;
        continue;
      }
      if (std::isspace(static_cast<unsigned char>(c)) || c == ',') space = true;
      ++i_;
    }
    return out;
  }

 private:
  // [+-] [spaces] number [*] [unit], or [+-] [spaces] unit.
  std::optional<Token> term(bool space_before) {
    std::size_t j = i_;
    double sign = 1;
    bool signed_term = false, gap = false;
    if (text_[j] == '+' || text_[j] == '-') {
      sign = text_[j] == '-' ? -1 : 1;
      signed_term = true;
      ++j;
      while (j < text_.size() && text_[j] == ' ') gap = true, ++j;
    }
    if (j >= text_.size()) return std::nullopt;
    const bool number_start =
        is_digit(text_[j]) || (text_[j] == '.' && j + 1 < text_.size() && is_digit(text_[j + 1]));
    const bool unit_start = (text_[j] == 'I' || text_[j] == 'i' || text_[j] == 'j') &&
                            (j + 1 >= text_.size() || !is_alpha(text_[j + 1]));
    if (!number_start && !(signed_term && unit_start)) return std::nullopt;
    double magnitude = 1;
    std::string bad;
    if (number_start) {
      std::size_t k = j;
      while (k < text_.size() &&
             (is_digit(text_[k]) || text_[k] == '.' || text_[k] == 'e' || text_[k] == 'E' ||
              ((text_[k] == '-' || text_[k] == '+') && (text_[k - 1] == 'e' || text_[k - 1] == 'E'))))
        ++k;
      const std::string number(text_.substr(j, k - j));
      char* end = nullptr;
      magnitude = std::strtod(number.c_str(), &end);
      if (end != number.c_str() + number.size() || !std::isfinite(magnitude))
        bad = "\"" + number + "\" is not a finite number";
      j = k;
    }
    bool imaginary = !number_start;
    std::size_t k = j;
    if (k < text_.size() && text_[k] == '*') ++k;
    if (k < text_.size() && (text_[k] == 'I' || text_[k] == 'i' || text_[k] == 'j') &&
        (k + 1 >= text_.size() || !is_alpha(text_[k + 1]))) {
      imaginary = true;
      j = k + 1;
    }
    const std::size_t begin = i_;
    i_ = j;
    const double x = sign * magnitude;
    return Token{Token::Term, imaginary ? Complex(0, x) : Complex(x, 0), imaginary, signed_term,
                 space_before, gap, line_, bad, begin, j};
  }

  std::string_view text_;
  std::size_t i_ = 0;
  int line_ = 1;
};

struct Entry {
  Complex value;
  int line;
  bool conj;  // a `conj` came before it
  std::string bad;
  std::size_t begin, end;  // its span in the text
};

// Joins "real <op> imaginary" into one entry: the sign written as an operator (spaces on
// both sides, or on neither).
std::vector<Entry> entries(const std::vector<Token>& tokens) {
  std::vector<Entry> out;
  bool conj = false;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (t.kind == Token::Conj) conj = true;
    if (t.kind != Token::Term) continue;
    Entry e{t.value, t.line, conj, t.bad, t.begin, t.end};
    conj = false;
    if (!t.imaginary && i + 1 < tokens.size()) {
      const Token& n = tokens[i + 1];
      const bool operator_sign = n.explicit_sign && n.space_before == n.space_after_sign;
      if (n.kind == Token::Term && n.imaginary && operator_sign) {
        e.value += n.value;
        if (e.bad.empty()) e.bad = n.bad;
        e.end = n.end;
        ++i;
      }
    }
    out.push_back(e);
  }
  return out;
}

}  // namespace

bool looks_like_moebius(std::string_view text) {
  const std::vector<Token> tokens = Scanner(text).tokens();
  // The first bracket group that holds entries and no bracket.
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (tokens[i].kind != Token::Open) continue;
    std::size_t j = i + 1;
    std::vector<Token> inner;
    while (j < tokens.size() && (tokens[j].kind == Token::Term || tokens[j].kind == Token::Conj))
      inner.push_back(tokens[j++]);
    if (j < tokens.size() && tokens[j].kind == Token::Close && !inner.empty())
      return entries(inner).size() == 2;
  }
  return false;
}

std::vector<std::pair<std::string_view, int>> moebius_entries(std::string_view text) {
  std::vector<std::pair<std::string_view, int>> out;
  for (const Entry& e : entries(Scanner(text).tokens()))
    out.emplace_back(text.substr(e.begin, e.end - e.begin), e.line);
  return out;
}

std::vector<MoebiusText> read_moebius(std::string_view text, const std::string& source) {
  const std::vector<Entry> all = entries(Scanner(text).tokens());
  for (std::size_t k = 0; k < all.size(); ++k)
    if (!all[k].bad.empty())
      throw SceneError(source + ": matrix " + std::to_string(k / 4 + 1) + " (line " +
                       std::to_string(all[k].line) + "): " + all[k].bad);
  std::vector<MoebiusText> out;
  if (all.size() % 4 != 0)
    throw SceneError(source + ": matrix " + std::to_string(all.size() / 4 + 1) + " (line " +
                     std::to_string(all.back().line) + "): has " + std::to_string(all.size() % 4) +
                     " entries, not 4 (Moebius matrices are 2x2 complex)");
  for (std::size_t k = 0; k < all.size(); k += 4) {
    MoebiusText m;
    m.line = all[k].line;
    m.t.reverses = all[k].conj;
    for (int i = 0; i < 4; ++i) m.t.abcd[i] = all[k + i].value;
    const Complex det = m.t.abcd[0] * m.t.abcd[3] - m.t.abcd[1] * m.t.abcd[2];
    double size = 0;
    for (const Complex& a : m.t.abcd) size = std::max(size, std::abs(a));
    if (!(std::abs(det) > 1e-12 * size * size))
      throw SceneError(source + ": matrix " + std::to_string(k / 4 + 1) + " (line " +
                       std::to_string(m.line) +
                       "): determinant ad - bc is 0: not a Moebius transformation");
    out.push_back(m);
  }
  return out;
}

}  // namespace geodesic
