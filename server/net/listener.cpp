#include "net/listener.h"

#include "net/http_session.h"

namespace geodesic::net {

Listener::Listener(asio::io_context& io, ServerContext& context, const tcp::endpoint& endpoint)
    : io_(io), context_(context), acceptor_(asio::make_strand(io)) {
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
  });
}

void Listener::accept() {
  // Each connection gets its own strand: its handlers never run concurrently.
  acceptor_.async_accept(asio::make_strand(io_),
                         beast::bind_front_handler(&Listener::on_accept, shared_from_this()));
}

void Listener::on_accept(beast::error_code ec, tcp::socket socket) {
  if (ec == asio::error::operation_aborted || !acceptor_.is_open()) return;  // stopped
  if (!ec) std::make_shared<HttpSession>(std::move(socket), context_)->start();
  accept();  // an error on one connection (e.g. too many open files) is not the listener's end
}

}  // namespace geodesic::net
