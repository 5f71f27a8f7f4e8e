#include "jobs/durable_file.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/statvfs.h>
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

// Image libraries word a full disk vaguely ("File output failed"): names the cause when the
// failed write of `file` ran out of room, else "". `error` is errno right after the failure.
std::string out_of_room(const std::filesystem::path& file, int error) {
  if (error == ENOSPC || error == EFBIG || error == EDQUOT) return std::strerror(error);
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  rlimit limit{};
  if (!ec && getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      size >= limit.rlim_cur)
    return std::string(std::strerror(EFBIG)) + " (the file-size limit, " +
           std::to_string(limit.rlim_cur) + " bytes)";
  struct statvfs disk{};
  if (statvfs(file.parent_path().c_str(), &disk) == 0 && disk.f_bavail == 0)
    return std::strerror(ENOSPC);
  return "";
}

}  // namespace

void write_durably(const std::filesystem::path& path,
                   const std::function<void(const std::filesystem::path&)>& write) {
  std::filesystem::path temporary = path;
  temporary.replace_filename(path.stem().string() + ".partial" + path.extension().string());
  try {
    errno = 0;
    write(temporary);
    fsync_path(temporary);
  } catch (const std::exception& e) {
    const std::string cause = out_of_room(temporary, errno);
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);  // a partial file only takes room
    throw std::runtime_error(path.string() + ": " + (cause.empty() ? "" : cause + "; ") + e.what());
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) throw std::runtime_error(path.string() + ": rename: " + ec.message());
  fsync_path(path.parent_path());
}

}  // namespace geodesic::jobs
