// `geodesic serve`: the render daemon. HTTP and WebSocket on one port (docs/protocol.md) until
// SIGINT or SIGTERM, which close the sessions gracefully.
#include <csignal>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <pthread.h>

#include "net/server.h"
#include "render/render_service.h"

namespace geodesic {
namespace {

net::ServerOptions parse(int argc, char** argv, std::string& device) {
  net::ServerOptions options;
  options.web_dir = GEODESIC_SOURCE_DIR "/web";
  for (int i = 0; i < argc; ++i) {
    const std::string flag = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(flag + ": needs a value");
      return argv[++i];
    };
    if (flag == "--host") {
      options.host = value();
    } else if (flag == "--port") {
      const std::string v = value();
      size_t used = 0;
      long port = -1;
      try { port = std::stol(v, &used); } catch (const std::exception&) { used = 0; }
      if (used != v.size() || port < 0 || port > 65535)
        throw std::invalid_argument("--port: must be an integer in [0, 65535], not \"" + v + "\"");
      options.port = static_cast<uint16_t>(port);
    } else if (flag == "--device") {
      device = value();
    } else if (flag == "--web") {
      options.web_dir = value();
    } else {
      throw std::invalid_argument("unknown option " + flag);
    }
  }
  return options;
}

}  // namespace

int serve_command(int argc, char** argv) {
  std::string device;
  const net::ServerOptions options = parse(argc, argv, device);

  // Block the stop signals before any thread starts (threads inherit the mask), then wait for
  // them synchronously on this thread: no work in a signal handler.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  RenderService render(device, GEODESIC_SOURCE_DIR "/scenes");
  net::Server server(render, options);
  std::printf("geodesic: serving http://%s:%u/ (WebSocket at /ws) on %s\n", options.host.c_str(),
              server.port(), render.stats().device.c_str());
  std::fflush(stdout);

  int signal = 0;
  sigwait(&stop_signals, &signal);
  std::printf("geodesic: %s, shutting down\n", signal == SIGINT ? "SIGINT" : "SIGTERM");
  server.stop();
  return 0;
}

}  // namespace geodesic
