// The error measure of error-against-run-time (docs/numerics.md, "Error estimate"): the relative
// RMS error of an image's luminance, measured against a reference, or estimated without one
// from two independent halves of the samples.
#pragma once

#include <cstddef>

#include "render/prepare/image.h"

namespace geodesic {

// sqrt(sum_p (L(image_p) - L(reference_p))^2 / sum_p L(reference_p)^2), L the Rec. 709
// luminance. Negative when the reference is black. The images must have the same size.
double relative_rmse(const Image& image, const Image& reference);

// The same quantity for the combined mean of two accumulation halves, estimated from their
// difference: `even` and `odd` hold 4 floats per pixel (rgb sums, sample count). With a, b the
// half means and n_a, n_b their counts, the combined mean c has variance
// Var(a - b) * n_a n_b / (n_a + n_b)^2 (a quarter of it when n_a = n_b), so with
//   D = sum_p (a_p - b_p)^2 n_a n_b / (n_a + n_b)^2   (estimates sum_p Var(c_p))
//   S = sum_p c_p^2                                   (estimates sum_p mu_p^2 + D)
//   error^2 = D / max(S - D, S / 2).
// Negative while some pixel lacks a sample in either half, or the image is black.
double estimated_relative_rmse(const float* even, const float* odd, size_t pixels);

}  // namespace geodesic
