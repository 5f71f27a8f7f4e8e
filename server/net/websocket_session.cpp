#include "net/websocket_session.h"

#include <mutex>
#include <stdexcept>
#include <utility>
#include <variant>

#include "net/preparation_pool.h"
#include "net/protocol.h"
#include "scene/scene.h"
#include "scene/scene_source.h"

namespace geodesic::net {
namespace {

using Clock = std::chrono::steady_clock;

// Replies queued beyond this pause reading: a client that floods bad messages without reading
// the errors cannot grow the queue.
constexpr std::size_t kMaxQueuedTexts = 16;
// How long a close may wait for a stuck write and the close handshake before the socket goes.
constexpr auto kCloseDeadline = std::chrono::seconds(5);
constexpr uint16_t kIdleTimeoutCode = 4000;
// A connection to a full server waits this long, this many times, for an idle session's slot.
constexpr int kEvictionRetries = 20;
constexpr auto kEvictionRetryDelay = std::chrono::milliseconds(50);

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
  // A full server: the longest-silent session gives up its slot while this one's first scene
  // is prepared, not after.
  RenderService& render = context_.render;
  if (render.stats().sessions >= render.limits().max_sessions) eviction_asked_ = evict_idle_session();
  // The first scene's renderer is built on the preparation pool, as every other one.
  auto build = [self = shared_from_this()] {
    auto first = std::make_shared<PreparedScene>();
    std::string failure;
    try {
      *first = self->context_.render.prepare_scene(SceneSource::bundled(kDefaultSceneName));
    } catch (const std::exception& e) {
      failure = e.what();
    }
    asio::post(self->ws_.get_executor(), [self, first, failure] {
      if (!failure.empty())
        return self->close(static_cast<uint16_t>(websocket::close_code::internal_error), failure);
      self->open_render_session(kEvictionRetries, first);
    });
  };
  if (!context_.preparation) return build();
  if (!context_.preparation->submit(build))
    close(static_cast<uint16_t>(websocket::close_code::try_again_later),
          "the server is busy preparing other scenes; try again shortly");
}

// A full server first asks its longest-silent session (no message for idle_eviction) to give up
// its slot, then tries again shortly; without one the client gets 1013.
void WebSocketSession::open_render_session(int retries, std::shared_ptr<PreparedScene> first) {
  RenderService& render = context_.render;
  try {
    id_ = render.open_session(
        std::move(*first),
        [relay = relay_](std::shared_ptr<const EncodedFrame> frame) { relay->deliver(frame); },
        [relay = relay_](const std::string& reason) { relay->fail(reason); });
  } catch (const std::exception& e) {
    if (retries > 0 && (retries < kEvictionRetries || eviction_asked_ || evict_idle_session())) {
      timer_.expires_after(kEvictionRetryDelay);
      timer_.async_wait([self = shared_from_this(), retries, first](beast::error_code ec) {
        if (!ec) self->open_render_session(retries - 1, first);
      });
      return;
    }
    close(static_cast<uint16_t>(websocket::close_code::try_again_later), e.what());
    return;
  }
  last_message_ = Clock::now();
  last_message_ticks_ = last_message_.time_since_epoch().count();
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
  last_message_ticks_ = last_message_.time_since_epoch().count();
  if (!close_reason_) {
    if (ws_.got_text())
      handle_message(beast::buffers_to_string(read_buffer_.data()));
    else
      send_text(error_message(ProtocolError("", "binary messages are not accepted")));
  }
  read_buffer_.consume(read_buffer_.size());
  if (preparing_) return;  // on_prepared reads on
  if (texts_.size() >= kMaxQueuedTexts)
    read_paused_ = true;
  else
    read();
}

// What the preparation pool made for an `open` (its scene) or for settings larger than the
// session's buffers (a renderer at the new size), or the error to send.
struct WebSocketSession::Prepared {
  ClientMessage message;
  std::optional<PreparedScene> scene;
  std::string error;    // an `error` message for the client
  std::string failure;  // an unexpected exception: the session closes with 1011
};

// Carries out a change a client asked for (`open` when it opens a scene): what is wrong with
// the request becomes an `error` message naming the field; anything else closes the session
// with 1011.
template <typename Change>
void WebSocketSession::apply_change(const OpenRequest* open, Change change) {
  try {
    change();
  } catch (const SceneError& e) {
    send_text(error_message(service_error(e, open)));
  } catch (const std::invalid_argument& e) {
    send_text(error_message(service_error(e, open)));
  } catch (const std::exception& e) {
    close(static_cast<uint16_t>(websocket::close_code::internal_error), e.what());
  }
}

// Runs the request on this strand; an `open`, and settings that need a new renderer, are
// prepared on the preparation pool.
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
  const auto* settings = std::get_if<SessionSettings>(&message);
  const auto* motion = std::get_if<CameraMotion>(&message);
  apply_change(open, [&] {
    if (context_.preparation && (open || (settings && !render.settings_fit(*id_, *settings)) ||
                                 (motion && render.move_outgrows_frame(*id_, *motion))))
      return prepare(std::move(message));
    if (open) {
      send_text(scene_message(render.load_scene(*id_, open->source())));
    } else if (motion) {
      render.move_camera(*id_, *motion);
    } else {
      render.apply_settings(*id_, *settings);
    }
    waiting_frame_.reset();  // rendered before the change
  });
}

// The scene (bundled scene, document, generator text) is parsed and its group enumerated under
// the pool's time budget, and its renderer built, on the preparation pool, then installed here;
// so are a renderer for larger settings and one centred on a camera that walked out of its
// renderer's frame. No further message is read meanwhile, so messages keep their order while
// frames go on.
void WebSocketSession::prepare(ClientMessage message) {
  preparing_ = true;
  const bool queued = context_.preparation->submit([self = shared_from_this(), message,
                                                    id = *id_] {
    Prepared prepared{message, std::nullopt, {}, {}};
    const auto* open = std::get_if<OpenRequest>(&message);
    try {
      const RenderService& render = self->context_.render;
      if (const auto* motion = std::get_if<CameraMotion>(&message)) {
        prepared.scene = render.prepare_move(id, *motion);
      } else if (!open) {
        prepared.scene = render.prepare_settings(id, std::get<SessionSettings>(message));
      } else {
        prepared.scene = render.prepare_scene(open->source());
      }
    } catch (const SceneError& e) {
      prepared.error = error_message(service_error(e, open));
    } catch (const std::invalid_argument& e) {
      prepared.error = error_message(service_error(e, open));
    } catch (const std::exception& e) {
      prepared.failure = e.what();
    }
    auto result = std::make_shared<Prepared>(std::move(prepared));
    asio::post(self->ws_.get_executor(), [self, result] { self->on_prepared(std::move(*result)); });
  });
  if (queued) return;
  preparing_ = false;
  send_text(error_message(service_error(
      std::runtime_error("the server is busy preparing other scenes; try again shortly"),
      std::get_if<OpenRequest>(&message))));
}

void WebSocketSession::on_prepared(Prepared prepared) {
  preparing_ = false;
  const auto* open = std::get_if<OpenRequest>(&prepared.message);
  if (id_ && !close_reason_) {
    RenderService& render = context_.render;
    apply_change(open, [&] {
      if (!prepared.failure.empty()) throw std::runtime_error(prepared.failure);
      if (!prepared.error.empty()) return send_text(std::move(prepared.error));
      if (open) {
        send_text(scene_message(render.install_scene(*id_, std::move(*prepared.scene))));
      } else if (const auto* motion = std::get_if<CameraMotion>(&prepared.message)) {
        render.move_camera(*id_, *motion);
        render.rebase(*id_, std::move(*prepared.scene));
      } else {
        if (prepared.scene) render.install_scene(*id_, std::move(*prepared.scene));
        render.apply_settings(*id_, std::get<SessionSettings>(prepared.message));
      }
      waiting_frame_.reset();  // rendered before the change
    });
  }
  if (texts_.size() >= kMaxQueuedTexts)
    read_paused_ = true;
  else
    read();
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

bool WebSocketSession::evict_idle_session() {
  const auto now = Clock::now().time_since_epoch().count();
  const auto limit = std::chrono::duration_cast<Clock::duration>(context_.options.idle_eviction).count();
  std::shared_ptr<WebSocketSession> quietest;
  for (auto& session : context_.sessions.live()) {
    const auto since = session->last_message_ticks_.load();
    if (session.get() == this || session->evicted_ || since == 0 || now - since < limit) continue;
    if (!quietest || since < quietest->last_message_ticks_.load()) quietest = std::move(session);
  }
  if (!quietest || quietest->evicted_.exchange(true)) return false;
  asio::post(quietest->ws_.get_executor(), [quietest] {
    quietest->release();  // its slot now: the waiting connection takes it
    quietest->close(kIdleTimeoutCode, "idle: no message for a while and the server is full");
  });
  return true;
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
