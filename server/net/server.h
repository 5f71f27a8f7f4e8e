// The daemon's network side: one port serving HTTP and, at /ws, WebSocket sessions backed by a
// RenderService, on a pool of I/O threads.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "net/beast.h"
#include "net/preparation_pool.h"
#include "net/server_context.h"

namespace geodesic::net {

class Listener;

class Server {
 public:
  // Binds (port 0: an ephemeral port) and starts serving. `render` and `jobs` (if any: the
  // jobs API) must outlive the server. Throws boost::system::system_error when the address
  // cannot be bound.
  Server(RenderService& render, ServerOptions options, jobs::JobQueue* jobs = nullptr);
  ~Server();  // stop()
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  uint16_t port() const;
  const NetCounters& counters() const { return context_.counters; }

  // Stops accepting, closes WebSocket sessions with 1001 (going away), lets them finish for up
  // to a grace period, then ends the I/O threads and every render session. Idempotent.
  void stop();

 private:
  ServerContext context_;  // declared first: sessions destroyed with io_ still use it
  PreparationPool preparation_;  // stopped first by stop(): its tasks post to io_
  asio::io_context io_;
  std::shared_ptr<Listener> listener_;
  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable threads_done_;
  int running_threads_ = 0;
  bool stopped_ = false;
};

}  // namespace geodesic::net
