#include "net/metrics.h"

#include <sstream>

namespace geodesic::net {
namespace {

template <typename T>
void metric(std::ostringstream& out, const char* name, const char* type, const char* help,
            T value) {
  out << "# HELP " << name << ' ' << help << "\n# TYPE " << name << ' ' << type << '\n'
      << name << ' ' << value << '\n';
}

}  // namespace

std::string prometheus_metrics(const ServiceStats& stats, const NetCounters& counters) {
  std::ostringstream out;
  out.precision(17);
  metric(out, "geodesic_sessions", "gauge", "Open render sessions.", stats.sessions);
  metric(out, "geodesic_frames_sent_total", "counter",
         "Frames (JSON + JPEG pairs) written to WebSocket clients.", counters.frames_sent.load());
  metric(out, "geodesic_frames_dropped_total", "counter",
         "Frames replaced by a newer one while waiting behind a slow client.",
         counters.frames_dropped.load());
  metric(out, "geodesic_samples_per_second", "gauge", "Pixel samples per second, recent.",
         stats.samples_per_second);
  metric(out, "geodesic_queue_depth", "gauge", "Sessions waiting for the render thread.",
         stats.queue_depth);
  metric(out, "geodesic_non_finite_samples_total", "counter",
         "Samples dropped as NaN or Inf, every session and job.", stats.non_finite_samples);
  metric(out, "geodesic_truncated_geodesics_total", "counter",
         "Geodesics cut off at the scene's max_crossings (returned black), every session and job.",
         stats.truncated_geodesics);
  out << "# HELP geodesic_jpeg_encode_seconds Time spent encoding JPEG frames.\n"
      << "# TYPE geodesic_jpeg_encode_seconds summary\n"
      << "geodesic_jpeg_encode_seconds_sum " << stats.encode_seconds_sum << '\n'
      << "geodesic_jpeg_encode_seconds_count " << stats.encode_count << '\n';
  return out.str();
}

}  // namespace geodesic::net
