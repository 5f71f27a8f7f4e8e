// What many test files share: one definition each, so that a unity build (tests/CMakeLists.txt
// compiles several test files as one) sees each once. Files in namespace geodesic take them
// with `using test::kPi;` and the like.
#pragma once

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "geometry/model.h"
#include "geometry/vec.h"

namespace geodesic::test {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kEps = DBL_EPSILON;
inline constexpr GeometryKind kE3 = GeometryKind::Euclidean, kH3 = GeometryKind::Hyperbolic,
                              kS3 = GeometryKind::Spherical;
// The source tree (scenes/, catalogue/, shaders/).
inline const std::filesystem::path kSource = GEODESIC_SOURCE_DIR;

// The largest difference between two matrices' entries.
inline double max_difference(const Mat4& a, const Mat4& b) {
  double d = 0;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(a.m[r][c] - b.m[r][c]));
  return d;
}

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace geodesic::test
