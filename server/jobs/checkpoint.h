// A running job's checkpoint: its accumulation buffers and sample count at the end of a pass,
// in one file replaced atomically (durable_file.h), so a killed daemon resumes from the last
// whole checkpoint. The header carries the job's fingerprint (its stored request, size and seed):
// a checkpoint left by another job (a restored or fresh store numbering jobs again) is never
// resumed, and a damaged one is only reported, never allocated for beyond the file's size.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <span>
#include <string>
#include <vector>

namespace geodesic::jobs {

// FNV-1a of the canonical request text, the image size and the seed.
uint64_t checkpoint_fingerprint(const std::string& request, int width, int height, uint64_t seed);

struct Checkpoint {
  uint32_t samples = 0;  // per pixel; the next sample index
  double elapsed = 0;    // seconds of rendering up to the checkpoint
  int width = 0, height = 0;
  std::vector<float> sums;  // Renderer::accumulation()
};

void write_checkpoint(const std::filesystem::path& path, uint64_t fingerprint, uint32_t samples,
                      double elapsed, int width, int height, std::span<const float> sums);
// nullopt when there is no checkpoint; throws CheckpointError for a file that is not one (bad
// magic, a size that disagrees with its header, a truncated body) or that belongs to a job
// with another fingerprint.
class CheckpointError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};
std::optional<Checkpoint> read_checkpoint(const std::filesystem::path& path, uint64_t fingerprint);

}  // namespace geodesic::jobs
