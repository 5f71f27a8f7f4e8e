#include "render/image_io.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <OpenImageIO/imageio.h>

namespace geodesic {

uint8_t to_srgb8(float linear) {
  float c = std::clamp(std::isfinite(linear) ? linear : 0.0f, 0.0f, 1.0f);
  float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return static_cast<uint8_t>(std::lround(s * 255.0f));
}

namespace {

float from_srgb8(uint8_t code) {
  float s = code / 255.0f;
  return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext;
}

}  // namespace

void check_output_format(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext != ".exr" && ext != ".png" && ext != ".jpg" && ext != ".jpeg")
    throw std::runtime_error(path.string() + ": unsupported output format \"" + ext +
                             "\" (use .exr, .png or .jpg)");
}

void write_image(const std::filesystem::path& path, const Image& image, float scale) {
  check_output_format(path);
  const std::string ext = lower_extension(path);
  const bool linear = ext == ".exr";
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw std::runtime_error(path.string() + ": " + OIIO::geterror());

  OIIO::ImageSpec spec(image.width, image.height, 3,
                       linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (!linear) spec.attribute("oiio:ColorSpace", "sRGB");
  if (ext == ".jpg" || ext == ".jpeg") spec.attribute("Compression", "jpeg:92");
  if (!out->open(path.string(), spec))
    throw std::runtime_error(path.string() + ": " + out->geterror());

  bool ok;
  if (linear) {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data());
  } else {
    std::vector<uint8_t> bytes(image.rgb.size());
    std::transform(image.rgb.begin(), image.rgb.end(), bytes.begin(),
                   [scale](float v) { return to_srgb8(v * scale); });
    ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  }
  if (!ok || !out->close()) throw std::runtime_error(path.string() + ": " + out->geterror());
}

Image read_image(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw std::runtime_error(path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  const bool srgb = spec.format == OIIO::TypeDesc::UINT8;
  std::vector<float> all(size_t(spec.width) * spec.height * spec.nchannels);
  if (srgb) {
    std::vector<uint8_t> bytes(all.size());
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, bytes.data()))
      throw std::runtime_error(path.string() + ": " + in->geterror());
    std::transform(bytes.begin(), bytes.end(), all.begin(), from_srgb8);
  } else if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data())) {
    throw std::runtime_error(path.string() + ": " + in->geterror());
  }
  image.rgb.resize(size_t(spec.width) * spec.height * 3);
  for (size_t p = 0; p < size_t(spec.width) * spec.height; ++p)
    for (int c = 0; c < 3; ++c)
      image.rgb[p * 3 + c] = all[p * spec.nchannels + std::min(c, spec.nchannels - 1)];
  return image;
}

}  // namespace geodesic
