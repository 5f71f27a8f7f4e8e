#include "net/server.h"

#include <chrono>

#include "net/listener.h"
#include "net/websocket_session.h"

namespace geodesic::net {
namespace {

// Time the close handshakes get on shutdown before the I/O threads are stopped.
// SIGTERM must end the daemon within 2 s whatever it is doing (docs/reliability.md).
constexpr auto kShutdownGrace = std::chrono::milliseconds(1000);

}  // namespace

Server::Server(RenderService& render, ServerOptions options, jobs::JobQueue* jobs)
    : context_{render, std::move(options), {}, {}, jobs},
      preparation_({context_.options.preparation_threads, 16, context_.options.preparation_seconds}),
      io_(context_.options.threads) {
  context_.preparation = &preparation_;
  const tcp::endpoint endpoint(asio::ip::make_address(context_.options.host),
                               context_.options.port);
  listener_ = std::make_shared<Listener>(io_, context_, endpoint);
  listener_->start();
  running_threads_ = context_.options.threads;
  for (int i = 0; i < context_.options.threads; ++i)
    threads_.emplace_back([this] {
      io_.run();
      std::lock_guard lock(mutex_);
      --running_threads_;
      threads_done_.notify_all();
    });
}

Server::~Server() { stop(); }

uint16_t Server::port() const { return listener_->port(); }

void Server::stop() {
  {
    std::lock_guard lock(mutex_);
    if (stopped_) return;
    stopped_ = true;
  }
  listener_->stop();
  // Running preparations stop at their next budget check; their connections are cut below.
  preparation_.stop();
  for (const auto& session : context_.sessions.live())
    session->close(static_cast<uint16_t>(websocket::close_code::going_away),
                   "server shutting down");
  {
    // The loop ends by itself once every connection is gone; idle keep-alive HTTP connections
    // and stuck clients are cut at the end of the grace period.
    std::unique_lock lock(mutex_);
    threads_done_.wait_for(lock, kShutdownGrace, [this] { return running_threads_ == 0; });
  }
  io_.stop();
  for (auto& thread : threads_) thread.join();
  // Sessions still held by pending handlers: end their render sessions before io_ (and so the
  // handlers) is destroyed, while the render thread may still be delivering frames.
  for (const auto& session : context_.sessions.live()) session->release();
}

}  // namespace geodesic::net
