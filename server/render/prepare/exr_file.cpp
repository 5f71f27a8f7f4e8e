#include "render/prepare/exr_file.h"

#include <algorithm>
#include <stdexcept>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

namespace geodesic {

int ExrImage::channel(const std::string& name) const {
  const auto it = std::find(channels.begin(), channels.end(), name);
  return it == channels.end() ? -1 : int(it - channels.begin());
}

void write_exr(const std::filesystem::path& path, const ExrImage& image) {
  const size_t count = image.channels.size();
  if (image.pixels.size() != size_t(image.width) * image.height * count)
    throw std::invalid_argument(path.string() + ": pixels and channels do not match");
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const auto& [name, value] : image.strings) header.insert(name, Imf::StringAttribute(value));
    for (const auto& [name, value] : image.integers) header.insert(name, Imf::IntAttribute(value));
    Imf::FrameBuffer frame;
    const size_t pixel = sizeof(float) * count;
    for (size_t c = 0; c < count; ++c) {
      header.channels().insert(image.channels[c], Imf::Channel(Imf::FLOAT));
      frame.insert(image.channels[c],
                   Imf::Slice(Imf::FLOAT, (char*)(image.pixels.data() + c), pixel, pixel * image.width));
    }
    Imf::OutputFile out(path.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(image.height);
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

ExrImage read_exr(const std::filesystem::path& path) {
  try {
    Imf::InputFile in(path.c_str());
    const Imf::Header& header = in.header();
    const Imath::Box2i window = header.dataWindow();
    ExrImage image;
    image.width = window.max.x - window.min.x + 1;
    image.height = window.max.y - window.min.y + 1;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
      image.channels.push_back(it.name());
    for (auto it = header.begin(); it != header.end(); ++it) {
      if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
        image.strings[it.name()] = s->value();
      else if (const auto* i = dynamic_cast<const Imf::IntAttribute*>(&it.attribute()))
        image.integers[it.name()] = i->value();
    }
    const size_t count = image.channels.size();
    image.pixels.assign(size_t(image.width) * image.height * count, 0.0f);
    Imf::FrameBuffer frame;
    const size_t pixel = sizeof(float) * count, row = pixel * image.width;
    // The slice's base is where pixel (0, 0) of the file's coordinates would lie.
    char* origin = (char*)image.pixels.data() - window.min.x * pixel - window.min.y * row;
    for (size_t c = 0; c < count; ++c)
      frame.insert(image.channels[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), pixel, row));
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

}  // namespace geodesic
