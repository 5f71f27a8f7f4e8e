#include "jobs/durable_file.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <unistd.h>

namespace geodesic::jobs {
namespace {

void fsync_path(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int error = errno;
    if (fd >= 0) ::close(fd);
    throw std::runtime_error(path.string() + ": fsync: " + std::strerror(error));
  }
  ::close(fd);
}

}  // namespace

void write_durably(const std::filesystem::path& path,
                   const std::function<void(const std::filesystem::path&)>& write) {
  std::filesystem::path temporary = path;
  temporary.replace_filename(path.stem().string() + ".partial" + path.extension().string());
  write(temporary);
  fsync_path(temporary);
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) throw std::runtime_error(path.string() + ": rename: " + ec.message());
  fsync_path(path.parent_path());
}

}  // namespace geodesic::jobs
