// A running job's checkpoint: its accumulation buffers and sample count at the end of a pass,
// in one file replaced atomically (durable_file.h), so a killed daemon resumes from the last
// whole checkpoint.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

namespace geodesic::jobs {

struct Checkpoint {
  uint32_t samples = 0;  // per pixel; the next sample index
  double elapsed = 0;    // seconds of rendering up to the checkpoint
  int width = 0, height = 0;
  std::vector<float> sums;  // Renderer::accumulation()
};

void write_checkpoint(const std::filesystem::path& path, uint32_t samples, double elapsed,
                      int width, int height, std::span<const float> sums);
// nullopt when there is no checkpoint; throws std::runtime_error for a file that is not one.
std::optional<Checkpoint> read_checkpoint(const std::filesystem::path& path);

}  // namespace geodesic::jobs
