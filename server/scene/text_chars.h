// Character classes the generator readers share (scene/generator_file.cpp, moebius_text.cpp).
#pragma once

#include <cctype>

namespace geodesic {

inline bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
// A letter or '_': what words are made of (with digits after the first).
inline bool is_alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_'; }

}  // namespace geodesic
