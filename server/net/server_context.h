// What every connection of one server shares: the render service, the options, the counters
// behind /metrics and the live WebSocket sessions (so a shutdown can close them).
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "render/service/render_service.h"

namespace geodesic::jobs {
class JobQueue;
}

namespace geodesic::net {

// Largest WebSocket message and HTTP request body accepted.
inline constexpr std::size_t kMaxMessageBytes = 1 << 20;

struct ServerOptions {
  std::string host = "127.0.0.1";
  uint16_t port = 8080;  // 0: an ephemeral port
  std::filesystem::path web_dir;
  // No client message for this long closes a WebSocket with 4000.
  std::chrono::milliseconds idle_timeout = std::chrono::minutes(10);
  // When every session slot is taken, a new connection takes the slot of a session that has
  // sent no message for this long (closed with 4000).
  std::chrono::milliseconds idle_eviction = std::chrono::seconds(60);
  // A whole HTTP request must arrive within this (slow senders cannot hold a connection).
  std::chrono::milliseconds http_timeout = std::chrono::seconds(30);
  // SO_SNDBUF of WebSocket connections in bytes; 0 leaves the kernel's autotuning (up to
  // net.ipv4.tcp_wmem's maximum, 4 MiB by default), which hides a slow reader for a while.
  int socket_send_buffer = 0;
  int threads = 2;
  // Scene preparation (generator enumeration, documents, meshes) off the I/O threads: worker
  // threads, and the time one preparation may take before it is refused with a named error.
  int preparation_threads = 2;
  double preparation_seconds = 10;
  // Bearer token the API, /metrics and /ws need (net/auth.h); empty: no auth.
  std::string token;
};

struct NetCounters {
  std::atomic<uint64_t> frames_sent{0};     // frame + JPEG pairs fully written
  std::atomic<uint64_t> frames_dropped{0};  // replaced while waiting behind a slow client
};

class WebSocketSession;
class PreparationPool;

class SessionRegistry {
 public:
  void add(const std::shared_ptr<WebSocketSession>& session) {
    std::lock_guard lock(mutex_);
    sessions_[session.get()] = session;
  }
  void remove(const WebSocketSession* session) {
    std::lock_guard lock(mutex_);
    sessions_.erase(session);
  }
  std::vector<std::shared_ptr<WebSocketSession>> live() const {
    std::lock_guard lock(mutex_);
    std::vector<std::shared_ptr<WebSocketSession>> result;
    for (const auto& [key, weak] : sessions_)
      if (auto session = weak.lock()) result.push_back(std::move(session));
    return result;
  }

 private:
  mutable std::mutex mutex_;
  std::map<const WebSocketSession*, std::weak_ptr<WebSocketSession>> sessions_;
};

struct ServerContext {
  RenderService& render;
  ServerOptions options;
  NetCounters counters;
  SessionRegistry sessions;
  jobs::JobQueue* jobs = nullptr;  // null: no jobs API (404)
  PreparationPool* preparation = nullptr;  // null: preparation runs on the I/O threads
};

}  // namespace geodesic::net
