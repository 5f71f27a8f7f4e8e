// Float EXR files through OpenEXR itself (Debian's libopenexr): the daemon's radiance results
// (RGB) and the sample-parallel accumulations (8 named channels with attributes). OpenEXR alone,
// not OpenImageIO, whose Debian build links every plugin's libraries (OpenVDB, GDAL, FFmpeg:
// hundreds of MB in the image) into any program that writes an image.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace geodesic {

struct ExrImage {
  int width = 0, height = 0;
  std::vector<std::string> channels;  // names, in the order of `pixels`' interleaving
  std::vector<float> pixels;          // row-major from the top row, channels interleaved
  std::map<std::string, std::string> strings;  // attributes
  std::map<std::string, int> integers;

  // A channel's index in `channels`, or -1.
  int channel(const std::string& name) const;
};

// ZIP-compressed 32-bit float channels. Throws std::runtime_error naming the path and the reason.
void write_exr(const std::filesystem::path& path, const ExrImage& image);

// Every channel as 32-bit float (half and uint channels converted), the string and int
// attributes. Throws std::runtime_error naming the path and the reason.
ExrImage read_exr(const std::filesystem::path& path);

}  // namespace geodesic
