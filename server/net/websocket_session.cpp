#include "net/websocket_session.h"

#include <mutex>
#include <stdexcept>
#include <utility>
#include <variant>

#include "net/protocol.h"
#include "scene/default_scene.h"
#include "scene/scene.h"

namespace geodesic::net {
namespace {

using Clock = std::chrono::steady_clock;

// Replies queued beyond this pause reading: a client that floods bad messages without reading
// the errors cannot grow the queue.
constexpr std::size_t kMaxQueuedTexts = 16;
// How long a close may wait for a stuck write and the close handshake before the socket goes.
constexpr auto kCloseDeadline = std::chrono::seconds(5);
constexpr uint16_t kIdleTimeoutCode = 4000;

websocket::close_reason make_reason(uint16_t code, std::string reason) {
  constexpr std::size_t kMaxReason = 123;  // a close frame's payload is 125 bytes
  if (reason.size() > kMaxReason) reason.resize(kMaxReason);
  return websocket::close_reason(static_cast<websocket::close_code>(code), reason);
}

}  // namespace

// Handed to the render service: forwards frames to the session's strand until cut. The render
// thread so never owns the session, and never posts once release() has returned.
struct WebSocketSession::FrameRelay {
  std::mutex mutex;
  bool open = true;
  std::weak_ptr<WebSocketSession> session;
  asio::any_io_executor strand;

  void deliver(std::shared_ptr<const EncodedFrame> frame) {
    std::lock_guard lock(mutex);
    if (!open) return;
    asio::post(strand, [session = session, frame = std::move(frame)]() mutable {
      if (auto s = session.lock()) s->on_frame(std::move(frame));
    });
  }
  void fail(const std::string& reason) {
    std::lock_guard lock(mutex);
    if (!open) return;
    asio::post(strand, [session = session, reason] {
      if (auto s = session.lock()) s->on_render_failed(reason);
    });
  }
  void cut() {
    std::lock_guard lock(mutex);
    open = false;
  }
};

WebSocketSession::WebSocketSession(tcp::socket&& socket, ServerContext& context)
    : context_(context), ws_(std::move(socket)), timer_(ws_.get_executor()) {}

WebSocketSession::~WebSocketSession() {
  release();
  context_.sessions.remove(this);
}

void WebSocketSession::start(http::request<http::string_body> upgrade) {
  // Beast's server timeouts: 30 s for the opening and closing handshakes, a ping after 150 s
  // without data and the end after 300 s, so dead peers go. kIdleTimeoutCode is separate: it is
  // about client messages, not pongs.
  ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  ws_.set_option(websocket::stream_base::decorator(
      [](websocket::response_type& res) { res.set(http::field::server, "geodesic"); }));
  ws_.read_message_max(kMaxMessageBytes);
  if (context_.options.socket_send_buffer > 0) {
    beast::error_code ignored;  // a refused size only means a larger kernel buffer
    beast::get_lowest_layer(ws_).socket().set_option(
        asio::socket_base::send_buffer_size(context_.options.socket_send_buffer), ignored);
  }
  ws_.async_accept(upgrade, beast::bind_front_handler(&WebSocketSession::on_accept,
                                                      shared_from_this()));
}

void WebSocketSession::on_accept(beast::error_code ec) {
  if (ec) return;
  relay_ = std::make_shared<FrameRelay>();
  relay_->session = weak_from_this();
  relay_->strand = ws_.get_executor();
  RenderService& render = context_.render;
  try {
    id_ = render.open_session(
        [relay = relay_](std::shared_ptr<const EncodedFrame> frame) { relay->deliver(frame); },
        [relay = relay_](const std::string& reason) { relay->fail(reason); });
  } catch (const std::exception& e) {
    close(static_cast<uint16_t>(websocket::close_code::try_again_later), e.what());
    return;
  }
  context_.sessions.add(shared_from_this());
  try {
    send_text(hello_message(*id_, render.bundled_scenes(), render.limits(), kMaxMessageBytes,
                            context_.options.idle_timeout));
    // Empty settings change nothing and answer the default scene's description.
    send_text(scene_message(render.apply_settings(*id_, {})));
  } catch (const std::exception& e) {
    close(static_cast<uint16_t>(websocket::close_code::internal_error), e.what());
    return;
  }
  last_message_ = Clock::now();
  arm_timer(last_message_ + context_.options.idle_timeout);
  read();
}

void WebSocketSession::read() {
  ws_.async_read(read_buffer_,
                 beast::bind_front_handler(&WebSocketSession::on_read, shared_from_this()));
}

void WebSocketSession::on_read(beast::error_code ec, std::size_t) {
  // Closed by the client, too big (Beast has answered 1009), or the connection is gone.
  if (ec) return finish();
  last_message_ = Clock::now();
  if (!close_reason_) {
    if (ws_.got_text())
      handle_message(beast::buffers_to_string(read_buffer_.data()));
    else
      send_text(error_message(ProtocolError("", "binary messages are not accepted")));
  }
  read_buffer_.consume(read_buffer_.size());
  if (texts_.size() >= kMaxQueuedTexts)
    read_paused_ = true;
  else
    read();
}

// Runs the request on this strand: loading a scene blocks one I/O thread for its duration.
void WebSocketSession::handle_message(const std::string& text) {
  if (!id_) return;
  RenderService& render = context_.render;
  ClientMessage message;
  try {
    message = parse_client_message(text, render.limits());
  } catch (const ProtocolError& e) {
    return send_text(error_message(e));
  }
  const OpenRequest* open = std::get_if<OpenRequest>(&message);
  try {
    if (open) {
      send_text(scene_message(
          open->scene        ? render.load_scene(*id_, *open->scene)
          : open->generators ? render.load_scene_document(
                                   *id_, generator_text_scene(*open->generators, "generators"))
                             : render.load_scene_document(*id_, *open->document)));
    } else if (const auto* motion = std::get_if<CameraMotion>(&message)) {
      render.move_camera(*id_, *motion);
    } else {
      render.apply_settings(*id_, std::get<SessionSettings>(message));
    }
    waiting_frame_.reset();  // rendered before the change
  } catch (const SceneError& e) {
    send_text(error_message(service_error(e, open)));
  } catch (const std::invalid_argument& e) {
    send_text(error_message(service_error(e, open)));
  } catch (const std::exception& e) {
    close(static_cast<uint16_t>(websocket::close_code::internal_error), e.what());
  }
}

void WebSocketSession::on_frame(std::shared_ptr<const EncodedFrame> frame) {
  if (!id_ || close_reason_) return;
  if (waiting_frame_) ++context_.counters.frames_dropped;
  waiting_frame_ = std::move(frame);
  pump();
}

// The render service has closed this session (a Vulkan error): the client gets an `error`
// naming it, then the close (1011); it may reconnect.
void WebSocketSession::on_render_failed(const std::string& reason) {
  if (!id_ || close_reason_) return;
  id_.reset();  // the service has closed it already
  waiting_frame_.reset();
  texts_.push_back(error_message(ProtocolError("", reason)));
  close_reason_ = make_reason(static_cast<uint16_t>(websocket::close_code::internal_error), reason);
  close_deadline_ = Clock::now() + kCloseDeadline;
  arm_timer(close_deadline_);
  pump();
}

void WebSocketSession::send_text(std::string text) {
  texts_.push_back(std::move(text));
  pump();
}

// Starts the next write when none is in flight: replies first, then the newest frame; a close
// waits for the replies still queued (close() drops them; a failed render queues its error).
void WebSocketSession::pump() {
  if (writing_ != Writing::nothing || close_started_) return;
  if (close_reason_ && texts_.empty()) return start_close();
  if (!texts_.empty()) {
    text_in_flight_ = std::move(texts_.front());
    texts_.pop_front();
    writing_ = Writing::text;
  } else if (waiting_frame_) {
    frame_in_flight_ = std::move(waiting_frame_);
    text_in_flight_ = frame_message(frame_in_flight_->info);
    writing_ = Writing::frame_text;
  } else {
    return;
  }
  ws_.text(true);
  ws_.async_write(asio::buffer(text_in_flight_),
                  beast::bind_front_handler(&WebSocketSession::on_write, shared_from_this()));
}

void WebSocketSession::on_write(beast::error_code ec, std::size_t) {
  if (ec) {
    writing_ = Writing::nothing;
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);  // ends a pending read too
    return finish();
  }
  if (writing_ == Writing::frame_text) {
    // The JPEG follows its `frame` message immediately: nothing may come between them.
    writing_ = Writing::frame_jpeg;
    ws_.binary(true);
    ws_.async_write(asio::buffer(frame_in_flight_->jpeg),
                    beast::bind_front_handler(&WebSocketSession::on_write, shared_from_this()));
    return;
  }
  if (writing_ == Writing::frame_jpeg) {
    ++context_.counters.frames_sent;
    frame_in_flight_.reset();
  }
  writing_ = Writing::nothing;
  if (read_paused_ && texts_.empty() && !close_reason_) {
    read_paused_ = false;
    read();
  }
  pump();
}

void WebSocketSession::close(uint16_t code, std::string reason) {
  asio::post(ws_.get_executor(), [self = shared_from_this(), code, reason = std::move(reason)] {
    if (self->close_reason_) return;
    self->close_reason_ = make_reason(code, reason);
    self->texts_.clear();
    self->waiting_frame_.reset();
    self->close_deadline_ = Clock::now() + kCloseDeadline;
    self->arm_timer(self->close_deadline_);
    self->pump();
  });
}

void WebSocketSession::start_close() {
  close_started_ = true;
  ws_.async_close(*close_reason_, [self = shared_from_this()](beast::error_code) {
    self->finish();
  });
}

// The connection is over: free the render session and stop the timer so nothing keeps this.
void WebSocketSession::finish() {
  release();
  timer_.cancel();
}

void WebSocketSession::release() {
  if (relay_) relay_->cut();
  if (id_) {
    const auto id = *id_;
    id_.reset();
    context_.render.close_session(id);
  }
  texts_.clear();
  waiting_frame_.reset();
}

void WebSocketSession::arm_timer(Clock::time_point at) {
  timer_.expires_at(at);
  timer_.async_wait(beast::bind_front_handler(&WebSocketSession::on_timer, shared_from_this()));
}

void WebSocketSession::on_timer(beast::error_code ec) {
  if (ec == asio::error::operation_aborted) return;
  const auto now = Clock::now();
  if (close_reason_) {
    if (now < close_deadline_) return arm_timer(close_deadline_);
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);  // the peer stopped reading
    return finish();
  }
  const auto idle_end = last_message_ + context_.options.idle_timeout;
  if (now < idle_end) return arm_timer(idle_end);
  close(kIdleTimeoutCode, "idle timeout: no message from the client");
}

}  // namespace geodesic::net
