// Isometries that carry points far out in H3 and back, without losing them to cancellation.
//
// A point of H3 at distance D from the origin has coordinates of size e^D / 2, and composing
// isometries that far out cancels products of size e^(2D): in double the relative position of
// two points 20 out, or a pose's frame there, is lost entirely (u e^40 = 26). The coordinates
// themselves stay good: rounded to double, a point 20 out still lies within 3e-8 of where it
// was, once it is projected back onto the hyperboloid (w from xyz). So this holds an H3
// isometry in binary128 (u e^40 = 2e-17), projects every point and pose it is given onto the
// model in that precision, and rounds only what it returns. Isometries that move the origin
// less than ~7.6 (entries up to 2^10, which double costs 10 bits of) and those of E3 and S3
// (E3's errors grow with D, not e^D; S3 is compact) compute in double: binary128 is software,
// ~4 us a point.
//
// Used by model::reorthonormalize (every pose the daemon reads or moves), by moved_scene and by
// the renderer's camera-centred frame (docs/numerics.md, "Far from the origin").
#pragma once

#include <array>

#include "geometry/model.h"

namespace geodesic {

#if defined(__SIZEOF_FLOAT128__)
using WideFloat = __float128;
#else
using WideFloat = long double;  // binary128 where __float128 is not offered (e.g. AArch64)
#endif
static_assert(sizeof(WideFloat) == 16, "WideIsometry needs a 113-bit floating-point type");

class WideIsometry {
 public:
  // The isometry nearest g, as model::reorthonormalize defines it (the image of the origin
  // projected onto the model, then Gram–Schmidt of columns 0-2 in the model's form).
  WideIsometry(GeometryKind k, const Mat4& g);

  WideIsometry inverse() const;
  WideIsometry operator*(const WideIsometry& other) const;  // this after other

  // The image of a point, projected onto the model before and after.
  Vec4 apply(const Vec4& point) const;
  // The image of a pose (reorthonormalised before and after): an isometry within double's
  // round-off, however far out the pose or its image lies.
  Mat4 apply(const Mat4& pose) const;
  // This isometry, rounded to double.
  const Mat4& matrix() const { return rounded_; }

  using Matrix = std::array<std::array<WideFloat, 4>, 4>;  // m[row][col], on column vectors

 private:
  WideIsometry(GeometryKind k, const Matrix& m, bool wide);
  GeometryKind kind_;
  bool wide_;  // computes in binary128
  Matrix matrix_;
  Mat4 rounded_;
};

}  // namespace geodesic
