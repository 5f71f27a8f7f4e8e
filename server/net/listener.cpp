#include "net/listener.h"

#include "net/http_session.h"

namespace geodesic::net {
namespace {

constexpr auto kAcceptBackoff = std::chrono::milliseconds(50);

}  // namespace

Listener::Listener(asio::io_context& io, ServerContext& context, const tcp::endpoint& endpoint)
    : io_(io), context_(context), acceptor_(asio::make_strand(io)), backoff_(acceptor_.get_executor()) {
  acceptor_.open(endpoint.protocol());
  acceptor_.set_option(asio::socket_base::reuse_address(true));
  acceptor_.bind(endpoint);
  acceptor_.listen(asio::socket_base::max_listen_connections);
  port_ = acceptor_.local_endpoint().port();
}

void Listener::start() {
  asio::dispatch(acceptor_.get_executor(),
                 beast::bind_front_handler(&Listener::accept, shared_from_this()));
}

void Listener::stop() {
  asio::post(acceptor_.get_executor(), [self = shared_from_this()] {
    beast::error_code ignored;
    self->acceptor_.close(ignored);
    self->backoff_.cancel();
  });
}

void Listener::accept() {
  // Each connection gets its own strand: its handlers never run concurrently.
  acceptor_.async_accept(asio::make_strand(io_),
                         beast::bind_front_handler(&Listener::on_accept, shared_from_this()));
}

void Listener::on_accept(beast::error_code ec, tcp::socket socket) {
  if (ec == asio::error::operation_aborted || !acceptor_.is_open()) return;  // stopped
  if (!ec) {
    std::make_shared<HttpSession>(std::move(socket), context_)->start();
    return accept();
  }
  // An error (too many open files: the pending connection stays queued and fails again at
  // once) is not the listener's end, but retrying at once would spin a core: wait a little.
  backoff_.expires_after(kAcceptBackoff);
  backoff_.async_wait([self = shared_from_this()](beast::error_code wait_error) {
    if (!wait_error && self->acceptor_.is_open()) self->accept();
  });
}

}  // namespace geodesic::net
