// One WebSocket connection at /ws: one render session, one strand. Frames come from the render
// thread and are posted to the strand; at most one frame (its `frame` text and JPEG) is being
// written and at most one waits, a newer frame replacing the waiting one, so a slow reader costs
// the server two frames of memory at most.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "net/beast.h"
#include "net/protocol.h"
#include "net/server_context.h"

namespace geodesic::net {

class WebSocketSession : public std::enable_shared_from_this<WebSocketSession> {
 public:
  WebSocketSession(tcp::socket&& socket, ServerContext& context);
  ~WebSocketSession();

  // Completes the upgrade that the HTTP session parsed.
  void start(http::request<http::string_body> upgrade);
  // Ends the session with a close frame once the write in flight is done; any thread.
  void close(uint16_t code, std::string reason);
  // Closes the render session and stops frame delivery. Idempotent; on the strand, or from the
  // server once no I/O thread runs.
  void release();

 private:
  struct FrameRelay;
  struct Prepared;
  enum class Writing { nothing, text, frame_text, frame_jpeg };

  void on_accept(beast::error_code ec);
  void open_render_session(int retries, std::shared_ptr<PreparedScene> first);
  // Asks the session silent longest (beyond idle_eviction) to give up its slot; false if none.
  bool evict_idle_session();
  void read();
  void on_read(beast::error_code ec, std::size_t bytes);
  template <typename Change>
  void apply_change(const OpenRequest* open, Change change);
  void handle_message(const std::string& text);
  void prepare(ClientMessage message);
  void on_prepared(Prepared prepared);
  void on_frame(std::shared_ptr<const EncodedFrame> frame);
  void on_render_failed(const std::string& reason);
  void send_text(std::string text);
  void pump();
  void on_write(beast::error_code ec, std::size_t bytes);
  void start_close();
  void finish();
  void arm_timer(std::chrono::steady_clock::time_point at);
  void on_timer(beast::error_code ec);

  ServerContext& context_;
  websocket::stream<beast::tcp_stream> ws_;
  asio::steady_timer timer_;  // the idle timeout, then the deadline of a close
  beast::flat_buffer read_buffer_;
  std::shared_ptr<FrameRelay> relay_;
  std::optional<RenderService::SessionId> id_;
  std::chrono::steady_clock::time_point last_message_;
  // last_message_ for other connections' threads (0 until the session is open).
  std::atomic<std::chrono::steady_clock::rep> last_message_ticks_{0};
  std::atomic<bool> evicted_{false};
  bool eviction_asked_ = false;  // this connection had an idle session give up its slot

  std::deque<std::string> texts_;  // hello, scene, error: sent before any waiting frame
  std::shared_ptr<const EncodedFrame> waiting_frame_;
  std::shared_ptr<const EncodedFrame> frame_in_flight_;
  std::string text_in_flight_;
  Writing writing_ = Writing::nothing;
  bool read_paused_ = false;  // too many replies queued: stop reading until they drain
  bool preparing_ = false;  // a message is on the preparation pool: read on once it is done

  std::optional<websocket::close_reason> close_reason_;  // set once closing is asked
  std::chrono::steady_clock::time_point close_deadline_;
  bool close_started_ = false;
};

}  // namespace geodesic::net
