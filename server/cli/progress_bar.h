// A progress line on stderr: redrawn in place on a terminal, silent otherwise (logs and CI
// get only the final summary).
#pragma once

#include <cstdio>
#include <string>

#include <unistd.h>

namespace geodesic {

class ProgressBar {
 public:
  ProgressBar() : tty_(isatty(STDERR_FILENO) != 0) {}

  // fraction in [0, 1]; label says what is done, e.g. "32/64 spp, 3.1 s".
  void update(double fraction, const std::string& label) {
    if (!tty_) return;
    constexpr int kWidth = 30;
    int filled = static_cast<int>(fraction * kWidth + 0.5);
    if (filled > kWidth) filled = kWidth;
    std::fprintf(stderr, "\r[%s%s] %3d%% %s\033[K", std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, ' ').c_str(), static_cast<int>(fraction * 100),
                 label.c_str());
    std::fflush(stderr);
  }

  void finish() {
    if (tty_) std::fprintf(stderr, "\r\033[K");
  }

 private:
  bool tty_;
};

}  // namespace geodesic
