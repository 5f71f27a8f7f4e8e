#include "render/prepare/jpeg_encoder.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <turbojpeg.h>

namespace geodesic {

JpegEncoder::JpegEncoder() : handle_(tjInitCompress()) {
  if (!handle_) throw std::runtime_error("TurboJPEG: cannot create a compressor");
}

JpegEncoder::~JpegEncoder() { tjDestroy(handle_); }

std::vector<unsigned char> JpegEncoder::encode(const Image& image, int quality, float scale) {
  rgb_.resize(image.rgb.size());
  std::transform(image.rgb.begin(), image.rgb.end(), rgb_.begin(),
                 [scale](float v) { return to_srgb8(v * scale); });
  unsigned char* jpeg = nullptr;
  unsigned long size = 0;
  if (tjCompress2(handle_, rgb_.data(), image.width, 0, image.height, TJPF_RGB, &jpeg, &size,
                  TJSAMP_420, quality, TJFLAG_FASTDCT) != 0)
    throw std::runtime_error(std::string("TurboJPEG: ") + tjGetErrorStr2(handle_));
  std::vector<unsigned char> out(jpeg, jpeg + size);
  tjFree(jpeg);
  return out;
}

}  // namespace geodesic
