// FrameEncoder (render/service/frame_encoder.h), the sessions' frames off the render thread: a frame is
// its pass resolved and encoded as the render thread did it before, frames come in order, a
// pass that arrives while the previous one waits replaces it, a new exposure encodes the last
// pass again, and a closed stream delivers nothing more.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "render/prepare/accumulation_file.h"
#include "render/prepare/exposure.h"
#include "render/service/frame_encoder.h"
#include "render/prepare/jpeg_encoder.h"
#include "render/prepare/relative_error.h"

namespace geodesic {
namespace {

constexpr int kWidth = 32, kHeight = 24;

// A pass of `spp` samples: each pixel's even and odd halves hold spp / 2 samples of a colour
// that varies over the image, the halves differing by noise.
PassSnapshot pass_of(uint32_t spp, Exposure exposure = {}) {
  PassSnapshot pass;
  const size_t pixels = size_t(kWidth) * kHeight;
  pass.sums.resize(2 * pixels * 4);
  std::mt19937 random(spp);
  std::uniform_real_distribution<float> noise(0.8f, 1.2f);
  for (size_t i = 0; i < 2 * pixels; ++i) {
    const float n = float(spp) / 2, x = float(i % pixels) / float(pixels);
    pass.sums[4 * i + 0] = n * x * noise(random);
    pass.sums[4 * i + 1] = n * 0.3f * noise(random);
    pass.sums[4 * i + 2] = n * (1 - x) * noise(random);
    pass.sums[4 * i + 3] = n;
  }
  pass.info.spp = spp;
  pass.info.width = kWidth;
  pass.info.height = kHeight;
  pass.exposure = exposure;
  return pass;
}

// Collects a stream's frames. While `hold` is set, a delivery waits until release().
class Frames {
 public:
  RenderService::FrameCallback callback() {
    return [this](std::shared_ptr<const EncodedFrame> frame) {
      std::unique_lock lock(mutex_);
      frames_.push_back(std::move(frame));
      changed_.notify_all();
      changed_.wait(lock, [this] { return !hold_; });
    };
  }
  void hold() { std::lock_guard lock(mutex_); hold_ = true; }
  void release() {
    std::lock_guard lock(mutex_);
    hold_ = false;
    changed_.notify_all();
  }
  // Waits (up to 10 s) for `count` frames; the frames so far.
  std::vector<std::shared_ptr<const EncodedFrame>> wait_for(size_t count) {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, std::chrono::seconds(10), [&] { return frames_.size() >= count; });
    return frames_;
  }
  std::vector<std::shared_ptr<const EncodedFrame>> all() {
    std::lock_guard lock(mutex_);
    return frames_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  bool hold_ = false;
  std::vector<std::shared_ptr<const EncodedFrame>> frames_;
};

// What the render thread sent for `pass` before the encoding moved off it.
std::vector<unsigned char> jpeg_of(const PassSnapshot& pass, double stops) {
  const float* even = pass.sums.data();
  const Image image = mean_image(even, even + pass.sums.size() / 2, kWidth, kHeight);
  return JpegEncoder().encode(image, 85, exposure_scale(stops));
}

TEST(FrameEncoder, AFrameIsItsPassResolvedAndEncoded) {
  Frames frames;
  FrameEncoder encoder(2);
  const PassSnapshot pass = pass_of(8, {.automatic = true});
  encoder.submit(encoder.open(frames.callback()), pass);
  const auto got = frames.wait_for(1);
  ASSERT_EQ(got.size(), 1u);
  const float* even = pass.sums.data();
  const Image image = mean_image(even, even + pass.sums.size() / 2, kWidth, kHeight);
  const double stops = automatic_stops(image);
  EXPECT_NE(stops, 0.0);
  EXPECT_EQ(got[0]->info.frame, 1u);
  EXPECT_EQ(got[0]->info.spp, 8u);
  EXPECT_EQ(got[0]->info.exposure, stops);
  EXPECT_EQ(got[0]->info.error,
            estimated_relative_rmse(even, even + pass.sums.size() / 2, size_t(kWidth) * kHeight));
  EXPECT_GT(got[0]->info.error, 0);
  EXPECT_EQ(got[0]->jpeg, jpeg_of(pass, stops));  // byte for byte
  EXPECT_EQ(encoder.counters().frames, 1u);
}

TEST(FrameEncoder, FramesComeInOrderAndANewerPassReplacesOneWaiting) {
  Frames frames;
  FrameEncoder encoder(2);
  const auto stream = encoder.open(frames.callback());
  frames.hold();
  encoder.submit(stream, pass_of(1));
  ASSERT_EQ(frames.wait_for(1).size(), 1u);  // delivering the first, held there
  for (uint32_t spp = 2; spp <= 4; ++spp) encoder.submit(stream, pass_of(spp));
  frames.release();
  const auto got = frames.wait_for(2);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[1]->info.frame, 2u);
  EXPECT_EQ(got[1]->info.spp, 4u);  // 2 and 3 were replaced while they waited
  EXPECT_EQ(got[1]->jpeg, jpeg_of(pass_of(4), 0));
}

TEST(FrameEncoder, ANewExposureEncodesTheLastPassAgainOrThePassWaiting) {
  Frames frames;
  {
    FrameEncoder encoder(1);
    const auto stream = encoder.open(frames.callback());
    encoder.reexpose(stream, {.stops = 3});  // no pass yet: nothing to show
    encoder.submit(stream, pass_of(4));
    ASSERT_EQ(frames.wait_for(1).size(), 1u);
    encoder.reexpose(stream, {.stops = 1});
    const auto again = frames.wait_for(2);
    ASSERT_EQ(again.size(), 2u);
    EXPECT_EQ(again[1]->info.frame, 2u);
    EXPECT_EQ(again[1]->info.spp, 4u);
    EXPECT_EQ(again[1]->info.exposure, 1.0);
    EXPECT_EQ(again[1]->jpeg, jpeg_of(pass_of(4), 1));

    frames.hold();
    encoder.submit(stream, pass_of(8));
    ASSERT_EQ(frames.wait_for(3).size(), 3u);
    encoder.submit(stream, pass_of(16));
    encoder.reexpose(stream, {.stops = 2});  // the pass waiting takes it
    frames.release();
    ASSERT_EQ(frames.wait_for(4).size(), 4u);
  }  // the workers joined: nothing more comes
  const auto got = frames.all();
  ASSERT_EQ(got.size(), 4u);
  EXPECT_EQ(got[3]->info.spp, 16u);
  EXPECT_EQ(got[3]->info.exposure, 2.0);
  EXPECT_EQ(got[3]->jpeg, jpeg_of(pass_of(16), 2));
}

TEST(FrameEncoder, AClosedStreamDeliversNothingMore) {
  Frames frames, other;
  {
    FrameEncoder encoder(2);
    const auto stream = encoder.open(frames.callback());
    const auto beside = encoder.open(other.callback());
    frames.hold();
    encoder.submit(stream, pass_of(1));
    ASSERT_EQ(frames.wait_for(1).size(), 1u);
    encoder.submit(stream, pass_of(2));  // waits behind the delivery held
    std::atomic<bool> closed{false};
    std::thread closer([&] {
      encoder.close(*stream);
      closed = true;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_FALSE(closed) << "close() returned during a delivery";
    frames.release();
    closer.join();
    encoder.submit(stream, pass_of(3));
    encoder.reexpose(stream, {.stops = 1});
    encoder.submit(beside, pass_of(5));  // the other stream goes on
    ASSERT_EQ(other.wait_for(1).size(), 1u);
  }  // the workers joined: whatever the closed stream had waiting is gone
  const auto got = frames.all();
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0]->info.spp, 1u);
  EXPECT_EQ(other.all().at(0)->info.spp, 5u);
}

}  // namespace
}  // namespace geodesic
