// Small double-precision vector and matrix types: the reference precision for all geometry.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace geodesic {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr Vec3() = default;
  constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
  constexpr Vec3 operator*(const Vec3& o) const { return {x * o.x, y * o.y, z * o.z}; }
  Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
};

constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
// The largest |coordinate|: the scale of a point, for relative tolerances (Vec4's below).
inline double max_abs(const Vec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& v) { return std::sqrt(dot(v, v)); }
inline Vec3 normalize(const Vec3& v) { return v / length(v); }

struct Vec4 {
  double x = 0, y = 0, z = 0, w = 0;

  constexpr Vec4() = default;
  constexpr Vec4(double x_, double y_, double z_, double w_) : x(x_), y(y_), z(z_), w(w_) {}
  constexpr Vec4(const Vec3& v, double w_) : x(v.x), y(v.y), z(v.z), w(w_) {}

  constexpr Vec3 xyz() const { return {x, y, z}; }
};

inline double max_abs(const Vec4& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z), std::abs(v.w)});
}

// 4x4 matrix acting on column vectors; m[row][col]. Isometries of every model geometry
// (E3 in homogeneous coordinates, H3 in R^{3,1}, S3 in R^4) are 4x4 matrices of this kind.
struct Mat4 {
  std::array<std::array<double, 4>, 4> m{};

  static constexpr Mat4 identity() {
    Mat4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1.0;
    return r;
  }

  constexpr Vec4 operator*(const Vec4& v) const {
    const double in[4] = {v.x, v.y, v.z, v.w};
    double out[4] = {0, 0, 0, 0};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) out[r] += m[r][c] * in[c];
    return {out[0], out[1], out[2], out[3]};
  }

  constexpr Mat4 operator*(const Mat4& o) const {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) r.m[i][j] += m[i][k] * o.m[k][j];
    return r;
  }

  // Column-major float layout, as GLSL's mat4 expects.
  std::array<float, 16> to_glsl() const {
    std::array<float, 16> out{};
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) out[c * 4 + r] = static_cast<float>(m[r][c]);
    return out;
  }

  // The largest |entry|: the scale of a matrix, for relative tolerances.
  double max_abs() const {
    double r = 0;
    for (const auto& row : m)
      for (double x : row) r = std::max(r, x < 0 ? -x : x);
    return r;
  }
};

}  // namespace geodesic
