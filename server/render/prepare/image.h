// A linear RGB float image, and its conversion to display values.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace geodesic {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;  // row-major from the top row, 3 floats per pixel

  float at(int x, int y, int channel) const { return rgb[(size_t(y) * width + x) * 3 + channel]; }
};

// sRGB transfer function of a linear value clamped to [0, 1], as an 8-bit code.
uint8_t to_srgb8(float linear);

}  // namespace geodesic
