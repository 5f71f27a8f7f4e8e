// Accepts TCP connections on one port; each becomes an HttpSession on its own strand.
#pragma once

#include <cstdint>
#include <memory>

#include "net/beast.h"
#include "net/server_context.h"

namespace geodesic::net {

class Listener : public std::enable_shared_from_this<Listener> {
 public:
  // Binds and listens; throws boost::system::system_error (port in use, bad address).
  Listener(asio::io_context& io, ServerContext& context, const tcp::endpoint& endpoint);

  uint16_t port() const { return port_; }
  void start();
  void stop();  // any thread: no more connections are accepted

 private:
  void accept();
  void on_accept(beast::error_code ec, tcp::socket socket);

  asio::io_context& io_;
  ServerContext& context_;
  tcp::acceptor acceptor_;
  asio::steady_timer backoff_;  // between failed accepts
  uint16_t port_ = 0;
};

}  // namespace geodesic::net
