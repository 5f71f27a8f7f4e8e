#include "render/service/frame_encoder.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <optional>
#include <utility>

#include "render/prepare/accumulation_file.h"
#include "render/prepare/exposure.h"
#include "render/prepare/jpeg_encoder.h"
#include "render/prepare/relative_error.h"

namespace geodesic {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kJpegQuality = 85;

}  // namespace

class FrameEncoder::Stream {
 public:
  explicit Stream(RenderService::FrameCallback on_frame) : on_frame_(std::move(on_frame)) {}

  // Guarded by FrameEncoder::mutex_: the work waiting, and whether the stream is in the ready
  // queue or being encoded (a strand: never on two workers at once).
  std::optional<PassSnapshot> pass;
  std::optional<Exposure> exposure;  // a re-exposure waiting
  bool queued = false;
  std::atomic<bool> closed{false};

  // On the one worker encoding the stream: `pass`, or the last image again with `exposure`.
  // Adds the JPEG encode's time to `jpeg_seconds`.
  std::shared_ptr<EncodedFrame> encode(JpegEncoder& jpeg, std::optional<PassSnapshot> next,
                                       const std::optional<Exposure>& exposure,
                                       double& jpeg_seconds) {
    if (next) {
      const size_t pixels = size_t(next->info.width) * size_t(next->info.height);
      const float* even = next->sums.data();
      last_image_ = mean_image(even, even + pixels * 4, next->info.width, next->info.height);
      last_info_ = next->info;
      last_info_.error = estimated_relative_rmse(even, even + pixels * 4, pixels);
    }
    if (last_image_.rgb.empty()) return nullptr;  // a re-exposure before any pass
    auto frame = std::make_shared<EncodedFrame>();
    frame->info = last_info_;
    frame->info.frame = ++frames_;
    frame->info.exposure = exposure_stops(exposure ? *exposure : next->exposure, last_image_);
    const auto start = Clock::now();
    frame->jpeg = jpeg.encode(last_image_, kJpegQuality, exposure_scale(frame->info.exposure));
    jpeg_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    return frame;
  }

  void deliver(std::shared_ptr<const EncodedFrame> frame) {
    std::lock_guard hold(delivery_);
    if (!closed && on_frame_) on_frame_(std::move(frame));
  }

  // Waits for a delivery under way (with `closed` set first, none starts after), then lets the
  // callback go on the closing thread: a worker may hold the stream a little longer, and what
  // the callback holds (a socket's strand) must not outlive the session's close (it would be
  // destroyed on the worker after its io_context).
  void release() {
    std::lock_guard hold(delivery_);
    on_frame_ = nullptr;
  }

 private:
  RenderService::FrameCallback on_frame_;
  std::mutex delivery_;
  // The encoding worker's own.
  Image last_image_;
  FrameInfo last_info_;
  uint64_t frames_ = 0;
};

FrameEncoder::FrameEncoder(int workers) {
  for (int i = 0; i < std::max(1, workers); ++i) workers_.emplace_back([this] { work(); });
}

FrameEncoder::~FrameEncoder() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  ready_changed_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

std::shared_ptr<FrameEncoder::Stream> FrameEncoder::open(RenderService::FrameCallback on_frame) {
  return std::make_shared<Stream>(std::move(on_frame));
}

void FrameEncoder::enqueue(const std::shared_ptr<Stream>& stream) {
  if (stream->queued) return;  // waiting already, or a worker takes it up again when done
  stream->queued = true;
  ready_.push_back(stream);
  ready_changed_.notify_one();
}

void FrameEncoder::submit(const std::shared_ptr<Stream>& stream, PassSnapshot pass) {
  std::lock_guard lock(mutex_);
  if (stream->closed) return;
  stream->pass = std::move(pass);
  stream->exposure.reset();  // the pass carries the session's exposure
  enqueue(stream);
}

void FrameEncoder::reexpose(const std::shared_ptr<Stream>& stream, const Exposure& exposure) {
  std::lock_guard lock(mutex_);
  if (stream->closed) return;
  if (stream->pass) stream->pass->exposure = exposure;
  else stream->exposure = exposure;
  enqueue(stream);
}

void FrameEncoder::close(Stream& stream) {
  {
    std::lock_guard lock(mutex_);
    stream.closed = true;
    stream.pass.reset();
    stream.exposure.reset();
  }
  stream.release();
}

FrameEncoder::Counters FrameEncoder::counters() const {
  std::lock_guard lock(mutex_);
  return counters_;
}

void FrameEncoder::work() {
  JpegEncoder jpeg;
  std::unique_lock lock(mutex_);
  for (;;) {
    ready_changed_.wait(lock, [this] { return stopping_ || !ready_.empty(); });
    if (stopping_) return;
    std::shared_ptr<Stream> stream = std::move(ready_.front());
    ready_.pop_front();
    std::optional<PassSnapshot> pass = std::exchange(stream->pass, std::nullopt);
    const std::optional<Exposure> exposure = std::exchange(stream->exposure, std::nullopt);
    lock.unlock();

    std::shared_ptr<EncodedFrame> frame;
    double seconds = 0;
    try {
      if (pass || exposure) frame = stream->encode(jpeg, std::move(pass), exposure, seconds);
    } catch (const std::exception& e) {  // the session goes on: its next pass is another try
      std::fprintf(stderr, "geodesic: a frame could not be encoded: %s\n", e.what());
    }
    if (frame) {
      {  // counted before the client can see it
        std::lock_guard count(mutex_);
        ++counters_.frames;
        counters_.encode_seconds_sum += seconds;
      }
      stream->deliver(std::move(frame));
    }

    lock.lock();
    // Work that came in meanwhile: behind the other streams waiting.
    stream->queued = false;
    if (!stream->closed && (stream->pass || stream->exposure)) enqueue(stream);
  }
}

}  // namespace geodesic
