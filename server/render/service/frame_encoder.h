// Resolves and encodes the sessions' frames off the render thread and outside the render
// service's lock, so that one session's JPEG encode never stalls the others' slices: the
// render thread copies a completed pass's accumulation under the lock (a memcpy) and submits
// it; a worker resolves it (the mean image, the error estimate, the automatic exposure),
// encodes the JPEG and hands it to the session's frame callback. Each session has a stream,
// a strand: its frames are encoded one at a time, in the order submitted. A pass submitted
// while the stream's previous one still waits replaces it (the newest frame wins, as on the
// socket), so at most one frame per session waits; once close() has returned, the stream
// delivers nothing more. Thread-safe; the workers never take the render service's lock.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "render/service/render_service.h"

namespace geodesic {

// A completed pass to show: its accumulation sums (the even half's pixels, then the odd
// half's, 4 floats each) and its frame's description, less what the encoding fills in (the
// frame number, the estimated error, the exposure's stops).
struct PassSnapshot {
  std::vector<float> sums;
  FrameInfo info;
  Exposure exposure;
};

class FrameEncoder {
 public:
  class Stream;

  // `workers` threads (at least one).
  explicit FrameEncoder(int workers);
  // Joins the workers; frames not yet encoded are dropped.
  ~FrameEncoder();
  FrameEncoder(const FrameEncoder&) = delete;
  FrameEncoder& operator=(const FrameEncoder&) = delete;

  // A session's stream; `on_frame` is called on a worker, one frame at a time.
  std::shared_ptr<Stream> open(RenderService::FrameCallback on_frame);
  // The next frame of `stream`: it replaces one that still waits.
  void submit(const std::shared_ptr<Stream>& stream, PassSnapshot pass);
  // The last pass's image encoded again with `exposure`; when a pass still waits, that pass is
  // encoded with it instead. Nothing when the stream has resolved no pass yet.
  void reexpose(const std::shared_ptr<Stream>& stream, const Exposure& exposure);
  // No frame of `stream` is delivered once this returns (it waits for one being delivered),
  // and its callback has been destroyed on the calling thread.
  void close(Stream& stream);

  struct Counters {
    uint64_t frames = 0;
    double encode_seconds_sum = 0;  // in the JPEG encoder
  };
  Counters counters() const;

 private:
  void work();
  void enqueue(const std::shared_ptr<Stream>& stream);  // under mutex_

  mutable std::mutex mutex_;  // guards everything below and the streams' waiting work
  std::condition_variable ready_changed_;
  std::deque<std::shared_ptr<Stream>> ready_;  // streams with work waiting, none being encoded
  bool stopping_ = false;
  Counters counters_;
  std::vector<std::thread> workers_;
};

}  // namespace geodesic
