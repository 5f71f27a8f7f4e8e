#include "render/prepare/image_io.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include <png.h>
#include <turbojpeg.h>

#include "render/prepare/exr_file.h"

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

namespace {

void write_file(const std::filesystem::path& path, const unsigned char* data, size_t size) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) throw std::runtime_error(path.string() + ": " + std::strerror(errno));
  const bool written = std::fwrite(data, 1, size, file) == size && std::fflush(file) == 0;
  const int error = errno;
  if (std::fclose(file) != 0 || !written)
    throw std::runtime_error(path.string() + ": " + std::strerror(written ? errno : error));
}

std::vector<unsigned char> read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open file");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_png(const std::filesystem::path& path, const std::vector<uint8_t>& bytes, int width, int height) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = uint32_t(width);
  png.height = uint32_t(height);
  png.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  if (!png_image_write_get_memory_size(png, size, 0, bytes.data(), 0, nullptr))
    throw std::runtime_error(path.string() + ": libpng: " + png.message);
  std::vector<unsigned char> encoded(size);
  if (!png_image_write_to_memory(&png, encoded.data(), &size, 0, bytes.data(), 0, nullptr))
    throw std::runtime_error(path.string() + ": libpng: " + png.message);
  write_file(path, encoded.data(), size);  // a short write is reported, unlike through stdio
}

void write_jpeg(const std::filesystem::path& path, const std::vector<uint8_t>& bytes, int width, int height) {
  tjhandle handle = tjInitCompress();
  unsigned char* jpeg = nullptr;
  unsigned long size = 0;
  const bool ok = handle && tjCompress2(handle, bytes.data(), width, 0, height, TJPF_RGB, &jpeg,
                                        &size, TJSAMP_420, 92, TJFLAG_ACCURATEDCT) == 0;
  const std::string error = handle ? tjGetErrorStr2(handle) : "no compressor";
  if (handle) tjDestroy(handle);
  if (!ok) {
    tjFree(jpeg);
    throw std::runtime_error(path.string() + ": TurboJPEG: " + error);
  }
  try {
    write_file(path, jpeg, size);
  } catch (...) {
    tjFree(jpeg);
    throw;
  }
  tjFree(jpeg);
}

// 8-bit sRGB RGB pixels of a PNG or JPEG file's bytes.
std::vector<uint8_t> decode_8bit(const std::filesystem::path& path, const std::vector<unsigned char>& data,
                                 int& width, int& height) {
  std::vector<uint8_t> rgb;
  if (data.size() >= 8 && png_sig_cmp(data.data(), 0, 8) == 0) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&png, data.data(), data.size()))
      throw std::runtime_error(path.string() + ": libpng: " + png.message);
    png.format = PNG_FORMAT_RGB;
    rgb.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, rgb.data(), 0, nullptr))
      throw std::runtime_error(path.string() + ": libpng: " + png.message);
    width = int(png.width);
    height = int(png.height);
    return rgb;
  }
  tjhandle handle = tjInitDecompress();
  int subsampling = 0, colourspace = 0;
  bool ok = handle && tjDecompressHeader3(handle, data.data(), data.size(), &width, &height,
                                          &subsampling, &colourspace) == 0;
  if (ok) {
    rgb.resize(size_t(width) * height * 3);
    ok = tjDecompress2(handle, data.data(), data.size(), rgb.data(), width, 0, height, TJPF_RGB,
                       TJFLAG_ACCURATEDCT) == 0;
  }
  const std::string error = handle ? tjGetErrorStr2(handle) : "no decompressor";
  if (handle) tjDestroy(handle);
  if (!ok) throw std::runtime_error(path.string() + ": not an EXR, PNG or JPEG image (" + error + ")");
  return rgb;
}

}  // namespace

void write_image(const std::filesystem::path& path, const Image& image, float scale) {
  check_output_format(path);
  const std::string ext = lower_extension(path);
  if (ext == ".exr") return write_exr(path, {image.width, image.height, {"R", "G", "B"}, image.rgb, {}, {}});
  std::vector<uint8_t> bytes(image.rgb.size());
  std::transform(image.rgb.begin(), image.rgb.end(), bytes.begin(),
                 [scale](float v) { return to_srgb8(v * scale); });
  if (ext == ".png") write_png(path, bytes, image.width, image.height);
  else write_jpeg(path, bytes, image.width, image.height);
}

Image read_image(const std::filesystem::path& path) {
  const std::vector<unsigned char> data = read_file(path);
  Image image;
  static const unsigned char kExrMagic[4] = {0x76, 0x2f, 0x31, 0x01};
  if (data.size() >= 4 && std::equal(kExrMagic, kExrMagic + 4, data.begin())) {
    const ExrImage exr = read_exr(path);
    image.width = exr.width;
    image.height = exr.height;
    // R, G and B by name; a one-channel file (Y, or any) is grey.
    int index[3];
    for (int c = 0; c < 3; ++c) {
      index[c] = exr.channel(std::string(1, "RGB"[c]));
      if (index[c] < 0) index[c] = exr.channel("Y") >= 0 ? exr.channel("Y") : 0;
    }
    const size_t pixels = size_t(exr.width) * exr.height, count = exr.channels.size();
    image.rgb.resize(pixels * 3);
    for (size_t p = 0; p < pixels; ++p)
      for (int c = 0; c < 3; ++c) image.rgb[p * 3 + c] = exr.pixels[p * count + index[c]];
    return image;
  }
  const std::vector<uint8_t> rgb = decode_8bit(path, data, image.width, image.height);
  image.rgb.resize(rgb.size());
  std::transform(rgb.begin(), rgb.end(), image.rgb.begin(), from_srgb8);
  return image;
}

}  // namespace geodesic
