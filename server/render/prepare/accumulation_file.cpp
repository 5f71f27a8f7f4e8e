#include "render/prepare/accumulation_file.h"

#include <algorithm>
#include <stdexcept>

#include "render/prepare/exr_file.h"
#include "render/prepare/relative_error.h"

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
  if (path.extension() != ".exr") throw std::runtime_error(fail(path, "an accumulation is written as .exr"));
  ExrImage exr{acc.width, acc.height, {std::begin(kChannels), std::end(kChannels)}, {}, {}, {}};
  exr.integers = {{"geodesic:sample_start", int(acc.sample_start)}, {"geodesic:samples", int(acc.samples)}};
  exr.strings = {{"geodesic:view", acc.view}};
  // Pixel-interleaved: the halves' 4 floats side by side.
  exr.pixels.resize(pixels * 8);
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 4; ++c) {
      exr.pixels[p * 8 + c] = acc.sums[p * 4 + c];
      exr.pixels[p * 8 + 4 + c] = acc.sums[(pixels + p) * 4 + c];
    }
  write_exr(path, exr);
}

Accumulation read_accumulation(const std::filesystem::path& path) {
  const ExrImage exr = read_exr(path);
  const auto view = exr.strings.find("geodesic:view");
  const auto start = exr.integers.find("geodesic:sample_start");
  const auto samples = exr.integers.find("geodesic:samples");
  if (view == exr.strings.end() || start == exr.integers.end() || samples == exr.integers.end() ||
      start->second < 0 || samples->second < 0 || exr.channels.size() != 8)
    throw std::runtime_error(fail(path, "not an accumulation (geodesic render --accumulation)"));
  // EXR stores channels by name (sorted): find each by its name.
  int index[8];
  for (int c = 0; c < 8; ++c) {
    index[c] = exr.channel(kChannels[c]);
    if (index[c] < 0) throw std::runtime_error(fail(path, "no channel " + std::string(kChannels[c])));
  }
  const size_t pixels = size_t(exr.width) * exr.height;
  Accumulation acc{exr.width, exr.height, uint32_t(start->second), uint32_t(samples->second), view->second, {}};
  acc.sums.resize(pixels * 8);
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 4; ++c) {
      acc.sums[p * 4 + c] = exr.pixels[p * 8 + index[c]];
      acc.sums[(pixels + p) * 4 + c] = exr.pixels[p * 8 + index[4 + c]];
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
