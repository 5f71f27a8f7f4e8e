// Sample-parallel rendering (docs: docker/README.md, "Scaling past one machine"): a render of a
// range of sample indices keeps its un-normalised accumulation (rgb sums and counts, even- and
// odd-numbered samples apart, as Renderer::accumulation() holds them) in an EXR file with its
// sample range; parts of disjoint ranges sum to the accumulation of their union, exactly up to
// float round-off, since every sample's random stream depends only on its index (and the seed).
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "render/prepare/image.h"

namespace geodesic {

struct Accumulation {
  int width = 0, height = 0;
  uint32_t sample_start = 0;  // the first sample index
  uint32_t samples = 0;       // sample indices [sample_start, sample_start + samples) per pixel
  // What the samples are of (scene, seed, depth, lighting): parts merge only when it matches.
  std::string view;
  std::vector<float> sums;    // 2 x width x height x (r, g, b, count): the even half, then odd

  // The running mean (Renderer::image()) and the error estimate of the two halves.
  Image image() const;
  double estimated_error() const;
};

// The mean of accumulation halves `even` and `odd` (4 floats per pixel: rgb sums, count).
Image mean_image(const float* even, const float* odd, int width, int height);

// An 8-channel float EXR (even.R/G/B/N, odd.R/G/B/N) with geodesic:* attributes; throws
// std::runtime_error naming the file on failure.
void write_accumulation(const std::filesystem::path& path, const Accumulation& acc);
Accumulation read_accumulation(const std::filesystem::path& path);

// The sum of parts of the same view and size over disjoint sample ranges, added in order of
// their first sample (in double, rounded once); its range starts at the first part's.
// Throws std::invalid_argument on a mismatch or an overlap.
Accumulation merge_accumulations(std::span<const Accumulation> parts);

}  // namespace geodesic
