// The error of an image against a reference, as bench/error_per_second.sh compares Geodesic with
// Cycles: relMSE = mean over pixels and channels of (x - r)^2 / (r^2 + 0.01) (the +0.01 keeps
// dark pixels from dominating), and each image's mean radiance per channel.
//   geodesic_image_error IMAGE REFERENCE   (EXR, PNG or JPEG; the same size)
// prints "relmse R" and "means r g b / r g b" (the image's, then the reference's).
#include <cstdio>
#include <exception>

#include "render/prepare/image_io.h"

using namespace geodesic;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: geodesic_image_error IMAGE REFERENCE\n");
    return 2;
  }
  try {
    const Image image = read_image(argv[1]), reference = read_image(argv[2]);
    if (image.width != reference.width || image.height != reference.height) {
      std::fprintf(stderr, "geodesic_image_error: %s is %dx%d, %s is %dx%d\n", argv[1], image.width,
                   image.height, argv[2], reference.width, reference.height);
      return 1;
    }
    double relmse = 0, mean[2][3] = {};
    const size_t values = image.rgb.size();
    for (size_t i = 0; i < values; ++i) {
      const double x = image.rgb[i], r = reference.rgb[i];
      relmse += (x - r) * (x - r) / (r * r + 0.01);
      mean[0][i % 3] += x;
      mean[1][i % 3] += r;
    }
    const double pixels = double(values / 3);
    std::printf("relmse %.6g\n", relmse / double(values));
    std::printf("means %.5f %.5f %.5f / %.5f %.5f %.5f\n", mean[0][0] / pixels, mean[0][1] / pixels,
                mean[0][2] / pixels, mean[1][0] / pixels, mean[1][1] / pixels, mean[1][2] / pixels);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "geodesic_image_error: %s\n", e.what());
    return 1;
  }
}
