// JPEG frames for streaming, with libjpeg-turbo (TurboJPEG): the fastest encoder Debian ships.
#pragma once

#include <vector>

#include "render/prepare/image.h"

namespace geodesic {

class JpegEncoder {
 public:
  JpegEncoder();
  ~JpegEncoder();
  JpegEncoder(const JpegEncoder&) = delete;
  JpegEncoder& operator=(const JpegEncoder&) = delete;

  // Scales (the exposure, render/prepare/exposure.h), tone-maps (sRGB, clamped) and encodes; quality
  // 1-100. Throws std::runtime_error.
  std::vector<unsigned char> encode(const Image& image, int quality = 85, float scale = 1);

 private:
  void* handle_;
  std::vector<unsigned char> rgb_;
};

}  // namespace geodesic
