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
constexpr char kMagic[8] = {'G', 'E', 'O', 'C', 'K', 'P', 'T', '1'};

struct Header {
  char magic[8];
  uint32_t samples;
  int32_t width, height;
  uint32_t reserved;
  double elapsed;
  uint64_t floats;
};

}  // namespace

void write_checkpoint(const std::filesystem::path& path, uint32_t samples, double elapsed,
                      int width, int height, std::span<const float> sums) {
  Header header{};
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

std::optional<Checkpoint> read_checkpoint(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  Header header{};
  in.read(reinterpret_cast<char*>(&header), sizeof header);
  const uint64_t expected = 2 * uint64_t(header.width) * uint64_t(header.height) * 4;
  if (!in || std::memcmp(header.magic, kMagic, sizeof kMagic) != 0 || header.width <= 0 ||
      header.height <= 0 || header.floats != expected)
    throw std::runtime_error(path.string() + ": not a checkpoint");
  Checkpoint checkpoint{header.samples, header.elapsed, header.width, header.height,
                        std::vector<float>(header.floats)};
  in.read(reinterpret_cast<char*>(checkpoint.sums.data()),
          std::streamsize(checkpoint.sums.size() * sizeof(float)));
  if (!in) throw std::runtime_error(path.string() + ": truncated checkpoint");
  return checkpoint;
}

}  // namespace geodesic::jobs
