#include "render/accumulation_file.h"

#include <algorithm>
#include <stdexcept>

#include <OpenImageIO/imageio.h>

#include "render/relative_error.h"

namespace geodesic {
namespace {

const char* const kChannels[8] = {"even.R", "even.G", "even.B", "even.N",
                                  "odd.R",  "odd.G",  "odd.B",  "odd.N"};

std::string fail(const std::filesystem::path& path, const std::string& why) {
  return path.string() + ": " + why;
}

}  // namespace

Image mean_image(const float* even, const float* odd, int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  const size_t pixels = size_t(width) * height;
  image.rgb.resize(pixels * 3);
  for (size_t p = 0; p < pixels; ++p) {
    const float count = even[p * 4 + 3] + odd[p * 4 + 3];
    for (int c = 0; c < 3; ++c)
      image.rgb[p * 3 + c] = count > 0 ? (even[p * 4 + c] + odd[p * 4 + c]) / count : 0;
  }
  return image;
}

Image Accumulation::image() const {
  const size_t pixels = size_t(width) * height;
  return mean_image(sums.data(), sums.data() + pixels * 4, width, height);
}

double Accumulation::estimated_error() const {
  const size_t pixels = size_t(width) * height;
  return estimated_relative_rmse(sums.data(), sums.data() + pixels * 4, pixels);
}

void write_accumulation(const std::filesystem::path& path, const Accumulation& acc) {
  const size_t pixels = size_t(acc.width) * acc.height;
  if (acc.sums.size() != pixels * 8) throw std::invalid_argument(fail(path, "bad accumulation size"));
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out || path.extension() != ".exr")
    throw std::runtime_error(fail(path, "an accumulation is written as .exr"));
  OIIO::ImageSpec spec(acc.width, acc.height, 8, OIIO::TypeDesc::FLOAT);
  spec.channelnames.assign(std::begin(kChannels), std::end(kChannels));
  spec.alpha_channel = -1;
  spec.attribute("compression", "zip");
  spec.attribute("geodesic:sample_start", int(acc.sample_start));
  spec.attribute("geodesic:samples", int(acc.samples));
  spec.attribute("geodesic:view", acc.view);
  // Pixel-interleaved: the halves' 4 floats side by side.
  std::vector<float> interleaved(pixels * 8);
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 4; ++c) {
      interleaved[p * 8 + c] = acc.sums[p * 4 + c];
      interleaved[p * 8 + 4 + c] = acc.sums[(pixels + p) * 4 + c];
    }
  if (!out->open(path.string(), spec) ||
      !out->write_image(OIIO::TypeDesc::FLOAT, interleaved.data()) || !out->close())
    throw std::runtime_error(fail(path, out->geterror()));
}

Accumulation read_accumulation(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw std::runtime_error(fail(path, OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  const std::string view = spec.get_string_attribute("geodesic:view");
  const int start = spec.get_int_attribute("geodesic:sample_start", -1);
  const int samples = spec.get_int_attribute("geodesic:samples", -1);
  if (start < 0 || samples < 0 || spec.nchannels != 8)
    throw std::runtime_error(fail(path, "not an accumulation (geodesic render --accumulation)"));
  // EXR stores channels by name (sorted): find each by its name.
  int index[8];
  for (int c = 0; c < 8; ++c) {
    const auto it = std::find(spec.channelnames.begin(), spec.channelnames.end(), kChannels[c]);
    if (it == spec.channelnames.end()) throw std::runtime_error(fail(path, "no channel " + std::string(kChannels[c])));
    index[c] = int(it - spec.channelnames.begin());
  }
  const size_t pixels = size_t(spec.width) * spec.height;
  std::vector<float> all(pixels * 8);
  if (!in->read_image(0, 0, 0, 8, OIIO::TypeDesc::FLOAT, all.data()))
    throw std::runtime_error(fail(path, in->geterror()));
  Accumulation acc{spec.width, spec.height, uint32_t(start), uint32_t(samples), view, {}};
  acc.sums.resize(pixels * 8);
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 4; ++c) {
      acc.sums[p * 4 + c] = all[p * 8 + index[c]];
      acc.sums[(pixels + p) * 4 + c] = all[p * 8 + index[4 + c]];
    }
  return acc;
}

Accumulation merge_accumulations(std::span<const Accumulation> parts) {
  if (parts.empty()) throw std::invalid_argument("merge: no parts");
  std::vector<const Accumulation*> order;
  for (const Accumulation& part : parts) order.push_back(&part);
  std::sort(order.begin(), order.end(),
            [](auto* a, auto* b) { return a->sample_start < b->sample_start; });
  const Accumulation& first = *order.front();
  std::vector<double> sum(first.sums.size(), 0.0);
  Accumulation merged{first.width, first.height, first.sample_start, 0, first.view, {}};
  uint64_t next = first.sample_start;
  for (const Accumulation* part : order) {
    if (part->width != first.width || part->height != first.height || part->view != first.view ||
        part->sums.size() != first.sums.size())
      throw std::invalid_argument("merge: parts of different renders (" + first.view + " " +
                                  std::to_string(first.width) + "x" + std::to_string(first.height) +
                                  " vs " + part->view + " " + std::to_string(part->width) + "x" +
                                  std::to_string(part->height) + ")");
    if (part->sample_start < next)
      throw std::invalid_argument("merge: sample ranges overlap at sample " +
                                  std::to_string(part->sample_start));
    next = uint64_t(part->sample_start) + part->samples;
    merged.samples += part->samples;
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += part->sums[i];
  }
  merged.sums.assign(sum.begin(), sum.end());
  return merged;
}

}  // namespace geodesic
