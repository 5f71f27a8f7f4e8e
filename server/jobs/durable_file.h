// Files that are either whole or absent after a crash: written under a temporary name, synced,
// then renamed over the final name (rename is atomic), and the folder synced so the new name
// itself survives a power cut.
#pragma once

#include <filesystem>
#include <functional>

namespace geodesic::jobs {

// Calls write(temporary) — which must create that file — then moves it to `path` durably.
// The temporary name keeps `path`'s extension (image writers pick the format from it). Throws
// std::runtime_error naming the path, and the cause when the disk or the file-size limit was
// reached ("No space left on device", "File too large"); a failed write leaves `path` as it was
// and no temporary file behind.
void write_durably(const std::filesystem::path& path,
                   const std::function<void(const std::filesystem::path&)>& write);

}  // namespace geodesic::jobs
