// The pass slicer (render/service/pass_slicer.h) on a stand-in renderer whose pixels cost what
// the test says, timed on a clock that only its dispatches advance: no slice runs far past its
// time when the cost of a pixel jumps 40-fold within a pass (the sky, then glass), and every
// pass still adds its samples to every pixel once. Slicing on a real renderer, and the same
// samples as one dispatch: tests/render/progressive_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "render/service/pass_slicer.h"
#include "render/service/render_service.h"

namespace geodesic::test {
namespace {

constexpr double kSlice = RenderService::kSliceSeconds;
constexpr double kDispatchSeconds = 70e-6;  // a submission on lavapipe
constexpr double kCheap = 1e-6, kDear = 40 * kCheap;  // seconds a pixel sample

using PixelCost = std::function<double(uint32_t column, uint32_t row)>;

class CostedTarget final : public SliceTarget {
 public:
  CostedTarget(int width, int height, PixelCost cost)
      : width_(width), height_(height), cost_(std::move(cost)), samples_(size_t(width) * height) {}

  int width() const override { return width_; }
  int height() const override { return height_; }
  double seconds() const override { return now_; }

  void render_region(uint32_t samples, const PixelRegion& region) override {
    ASSERT_LE(region.column + region.columns, uint32_t(width_));
    ASSERT_LE(region.row + region.rows, uint32_t(height_));
    ASSERT_GT(region.columns * region.rows, 0u);
    now_ += kDispatchSeconds;
    for (uint32_t row = region.row; row < region.row + region.rows; ++row)
      for (uint32_t column = region.column; column < region.column + region.columns; ++column) {
        now_ += cost_(column, row) * samples;
        samples_[size_t(row) * width_ + column] += samples;
      }
    ++dispatches;
  }

  // Every pixel has had the pass's samples, once.
  void finish_pass(uint32_t samples) override {
    finished += samples;
    for (uint32_t s : samples_) ASSERT_EQ(s, finished);
  }

  uint32_t finished = 0;
  int dispatches = 0;

 private:
  int width_, height_;
  PixelCost cost_;
  std::vector<uint32_t> samples_;
  double now_ = 1000;
};

struct Pass {
  double worst = 0;    // the longest slice, seconds on the target's clock
  double seconds = 0;  // all slices
  int slices = 0, dispatches = 0;
};

// Renders `count` passes; what the slices of each took.
std::vector<Pass> render_passes(PassSlicer& slicer, CostedTarget& target, int count) {
  std::vector<Pass> passes(count);
  for (Pass& pass : passes) {
    const int dispatches = target.dispatches;
    for (bool done = false; !done;) {
      const double start = target.seconds();
      done = slicer.render_slice(target);
      const double took = target.seconds() - start;
      EXPECT_NEAR(slicer.last_seconds(), took, 1e-9);
      pass.worst = std::max(pass.worst, took);
      pass.seconds += took;
      ++pass.slices;
    }
    pass.dispatches = target.dispatches - dispatches;
  }
  return passes;
}

// A 1280 x 256 image whose first 96 rows are sky and the rest glass (40 times the cost): the
// first pass learns the sky's cost, on which a 40 ms slice is 25,000 pixels or 1 s of glass.
// A guessed dispatch is 1/32 of a slice, so a slice ends by 1 + 39/32 = 2.2 slices at most
// (1.8 here; sized as one dispatch, as before, the worst took 1.18 s in the first pass and
// 1.03 s in each later one).
TEST(PassSlicer, NoSliceOverrunsFarWhenTheCostJumps40FoldMidPass) {
  CostedTarget target(1280, 256, [](uint32_t, uint32_t row) { return row < 96 ? kCheap : kDear; });
  PassSlicer slicer(kSlice);
  const std::vector<Pass> passes = render_passes(slicer, target, 3);
  EXPECT_EQ(target.finished, 3u);  // one sample a pass: none fits in a slice
  for (const Pass& pass : passes) {
    EXPECT_LT(pass.worst, 2.5 * kSlice);
    // Nor are they cut short: a slice ends when less than 1/32 of its time is left.
    EXPECT_GT(pass.seconds / pass.slices, 0.9 * kSlice);
  }
  // The first pass guesses the glass's cost from the sky's, in dispatches of 1/32 of a slice or
  // more (their submissions under 5 % of its time); the later passes know each pixel's cost
  // from the one before, and a slice is one dispatch or two (whole rows, then part of one).
  EXPECT_LT(passes[0].dispatches * kDispatchSeconds, 0.05 * passes[0].seconds);
  for (size_t i = 1; i < passes.size(); ++i)
    EXPECT_LE(passes[i].dispatches, 2 * passes[i].slices);
}

// Glass spheres scattered over the sky: the cost jumps up and down along every row.
TEST(PassSlicer, NoSliceOverrunsFarWhenDearPixelsAreScattered) {
  const auto glass = [](uint32_t column, uint32_t row) {
    for (int i = 0; i < 12; ++i) {  // disks of radius 40 on a fixed pattern
      const double x = 60 + (i * 397) % 1160, y = 50 + (i * 151) % 300;
      if (std::hypot(column - x, row - y) < 40) return kDear;
    }
    return kCheap;
  };
  CostedTarget target(1280, 400, glass);
  PassSlicer slicer(kSlice);
  for (const Pass& pass : render_passes(slicer, target, 3)) {
    EXPECT_LT(pass.worst, 2.5 * kSlice);
    EXPECT_GT(pass.seconds / pass.slices, 0.9 * kSlice);
  }
  EXPECT_EQ(target.finished, 3u);
}

// A new view starts its pixels' costs over (its first pass guesses again); a cheap one soon fits
// in one slice, one dispatch, and its batch doubles.
TEST(PassSlicer, ANewViewGuessesAgainAndACheapPassIsOneDispatch) {
  bool dear = true;
  CostedTarget target(320, 240, [&](uint32_t, uint32_t row) {
    return !dear ? kCheap / 10 : row < 120 ? kCheap : kDear;
  });
  PassSlicer slicer(kSlice);
  render_passes(slicer, target, 2);
  dear = false;  // the view turns to the sky: 8 ms a pass
  slicer.restart();
  const std::vector<Pass> passes = render_passes(slicer, target, 4);
  EXPECT_GT(passes[0].dispatches, 1);  // guessed
  EXPECT_EQ(passes[1].dispatches, 1);  // known from the first
  for (const Pass& pass : passes) EXPECT_LT(pass.worst, 2.5 * kSlice);
  EXPECT_GT(slicer.batch(), 1u);
  const Pass last = render_passes(slicer, target, 1)[0];
  EXPECT_EQ(last.slices, 1);
  EXPECT_EQ(last.dispatches, 1);
}

// A GPU: a dispatch takes as long as its longest path (kFloor, one thread's chain of
// traversals) or as its pixel samples at the device's rate, whichever is longer.
class GpuTarget final : public SliceTarget {
 public:
  static constexpr double kFloor = 3e-3, kPerSample = 30e-9;
  GpuTarget(int width, int height, double parallel)
      : width_(width), height_(height), parallel_(parallel) {}
  int width() const override { return width_; }
  int height() const override { return height_; }
  double seconds() const override { return now_; }
  double parallel_pixel_samples() const override { return parallel_; }
  void render_region(uint32_t samples, const PixelRegion& region) override {
    now_ += 20e-6 + std::max(kFloor, kPerSample * samples * region.columns * region.rows);
    ++dispatches;
  }
  void finish_pass(uint32_t) override {}
  void resize(int width, int height) { width_ = width, height_ = height; }
  int dispatches = 0;

 private:
  int width_, height_;
  double parallel_;
  double now_ = 1000;
};

// The cost a GPU's slicer learns: close to its rate, so that a moving view (render_session.cpp
// sizes it from seconds_per_pixel_sample()) keeps most of its pixels, and a walk's small views
// take a dispatch or two each. Counted per pixel of a small dispatch, the same device looked 20
// times dearer: moving views went to 80 px wide and took dozens of dispatches at the floor.
TEST(PassSlicer, AGpusSmallDispatchesDoNotMakeItsPixelsLookDear) {
  GpuTarget gpu(640, 480, PassSlicer::kGpuParallelPixelSamples);
  PassSlicer slicer(kSlice);
  while (!slicer.render_slice(gpu)) {}
  EXPECT_LT(slicer.seconds_per_pixel_sample(), 2 * GpuTarget::kPerSample);
  for (int move = 0; move < 20; ++move) {  // a walk: each view 320 x 240, one pass each
    gpu.resize(320, 240);
    slicer.restart();
    const int dispatches = gpu.dispatches;
    const double start = gpu.seconds();
    EXPECT_TRUE(slicer.render_slice(gpu));  // the whole view in one slice
    EXPECT_LE(gpu.dispatches - dispatches, 2);  // 65536 pixels, then the rest
    EXPECT_LT(gpu.seconds() - start, 2 * GpuTarget::kFloor + 320 * 240 * GpuTarget::kPerSample);
  }
  EXPECT_LT(slicer.seconds_per_pixel_sample(), 2 * GpuTarget::kPerSample);

  GpuTarget counted_per_pixel(640, 480, 1);
  PassSlicer fooled(kSlice);
  while (!fooled.render_slice(counted_per_pixel)) {}
  EXPECT_GT(fooled.seconds_per_pixel_sample(), 20 * GpuTarget::kPerSample);
}

}  // namespace
}  // namespace geodesic::test
