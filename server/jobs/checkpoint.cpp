#include "jobs/checkpoint.h"

#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "jobs/durable_file.h"

namespace geodesic::jobs {
namespace {

// Magic and version, then the header (fixed layout, native byte order: a checkpoint only
// resumes on the machine that wrote it), then the sums.
constexpr char kMagic[8] = {'G', 'E', 'O', 'C', 'K', 'P', 'T', '2'};

struct Header {
  char magic[8];
  uint32_t samples;
  int32_t width, height;
  uint32_t reserved;
  double elapsed;
  uint64_t floats;
  uint64_t fingerprint;
};

// Largest image a checkpoint may describe (the service's limits are far below).
constexpr int64_t kMaxSide = 16384;

}  // namespace

uint64_t checkpoint_fingerprint(const std::string& request, int width, int height,
                                uint64_t seed) {
  uint64_t hash = 1469598103934665603ull;
  const auto mix = [&](const void* data, std::size_t size) {
    for (std::size_t i = 0; i < size; ++i) {
      hash ^= static_cast<const unsigned char*>(data)[i];
      hash *= 1099511628211ull;
    }
  };
  mix(request.data(), request.size());
  mix(&width, sizeof width);
  mix(&height, sizeof height);
  mix(&seed, sizeof seed);
  return hash;
}

void write_checkpoint(const std::filesystem::path& path, uint64_t fingerprint, uint32_t samples,
                      double elapsed, int width, int height, std::span<const float> sums) {
  Header header{};
  header.fingerprint = fingerprint;
  std::memcpy(header.magic, kMagic, sizeof kMagic);
  header.samples = samples;
  header.width = width;
  header.height = height;
  header.elapsed = elapsed;
  header.floats = sums.size();
  write_durably(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(&header), sizeof header);
    out.write(reinterpret_cast<const char*>(sums.data()), std::streamsize(sums.size_bytes()));
    out.close();
    if (!out) throw std::runtime_error(temporary.string() + ": cannot write the checkpoint");
  });
}

std::optional<Checkpoint> read_checkpoint(const std::filesystem::path& path, uint64_t fingerprint) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::error_code ec;
  const uint64_t file_size = std::filesystem::file_size(path, ec);
  Header header{};
  in.read(reinterpret_cast<char*>(&header), sizeof header);
  if (ec || !in || std::memcmp(header.magic, kMagic, sizeof kMagic) != 0)
    throw CheckpointError("checkpoint: not a checkpoint (bad header)");
  if (header.width <= 0 || header.height <= 0 || header.width > kMaxSide || header.height > kMaxSide ||
      header.floats != 2 * uint64_t(header.width) * uint64_t(header.height) * 4 ||
      file_size != sizeof header + header.floats * sizeof(float) || !(header.elapsed >= 0))
    throw CheckpointError("checkpoint: its header disagrees with its size (" +
                          std::to_string(file_size) + " bytes)");
  if (header.fingerprint != fingerprint)
    throw CheckpointError("checkpoint: belongs to another job (fingerprint differs)");
  Checkpoint checkpoint{header.samples, header.elapsed, header.width, header.height,
                        std::vector<float>(header.floats)};
  in.read(reinterpret_cast<char*>(checkpoint.sums.data()),
          std::streamsize(checkpoint.sums.size() * sizeof(float)));
  if (!in) throw CheckpointError("checkpoint: truncated");
  return checkpoint;
}

}  // namespace geodesic::jobs
