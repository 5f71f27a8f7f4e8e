// Cuts the passes of a progressive render into slices of about a given device time, so that
// whoever shares the device (the render thread's other sessions, a camera move, the render
// jobs) waits at most about one slice, whatever the scene costs: a pass adds batch() samples to
// every pixel, and a slice renders as many pixels of it, in row order, as fit in the slice:
// whole rows when a row fits, otherwise part of one row (a 1920-pixel row of a scene with a
// thousand lights can take seconds). A pass that fits in one slice in under half its time
// doubles the batch for the next (up to the slicer's largest batch), one that takes two slices'
// time halves it. The one scheduler of passes: the render service keeps one per session, a
// render job one for itself, and `geodesic render` one for its render (quarter-second passes:
// slices of half a second, batches up to 64).
//
// What fits is judged from measured costs, and a pixel can cost many times its neighbours (sky,
// then glass with many bounces), so a slice is one or more dispatches with a clock check
// between, and ends when its time is spent:
// - pixels that the last whole pass of this view rendered cost what it measured there: as many
//   as fit in the time left go in one dispatch (a still view's later passes: one dispatch);
// - the others (a new view's first pass) cost a guess: what the pixels just before them in row
//   order cost (at a pass's start, the cost measured so far, slice by slice: a rising cost
//   adopted at once, a falling one smoothed). They go in dispatches of at most 1/kUnprovenSplit
//   of the slice's time (kFirstPixels pixels at least, if those fit), so a guess n times too low
//   overruns the slice by at most n/kUnprovenSplit of it (pixels 40 times dearer than the ones
//   before: 2.2 slices at most, where a slice of one dispatch could take 40), and the next
//   dispatch's guess is their cost.
#pragma once

#include <cstdint>
#include <vector>

#include "render/device/renderer.h"

namespace geodesic {

// What a slicer renders: a Renderer (render_slice(Renderer&) wraps one) or, in the tests, a
// stand-in with the costs and the clock they choose.
class SliceTarget {
 public:
  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual void render_region(uint32_t samples, const PixelRegion& region) = 0;
  virtual void finish_pass(uint32_t samples) = 0;
  // Seconds on a steady clock: slices are timed on it.
  virtual double seconds() const;
  // The pixel samples a dispatch needs to keep the device's cores busy: a smaller one takes
  // about as long. 1 on a CPU, whose few cores a handful of pixels fill; a GPU's dispatch of a
  // few pixels takes as long as their longest path, one thread's chain of traversals.
  virtual double parallel_pixel_samples() const { return 1; }

 protected:
  ~SliceTarget() = default;
};

class PassSlicer {
 public:
  static constexpr uint32_t kMaxBatch = 256;  // the default: larger passes are not faster
  // Pixels in the first slice, before the cost is known, and in a guessed dispatch at least
  // (or the target's parallel_pixel_samples(), where more).
  static constexpr uint64_t kFirstPixels = 64;
  // parallel_pixel_samples() of a GPU: a few times the threads its cores hold at once.
  static constexpr double kGpuParallelPixelSamples = 65536;
  // A slice has at most this many times the pixel samples of the largest one so far: a new
  // scene's first slices grow from kFirstPixels (64, 256, 1024, ...) as its cost is learnt.
  static constexpr double kMaxGrowth = 4;
  // Pixels whose cost is a guess go in dispatches of at most 1/kUnprovenSplit of the slice's
  // time. Each dispatch costs about 70 us of submission on lavapipe: 2 ms in a 40 ms slice of
  // guesses, none in a still view's later passes.
  static constexpr double kUnprovenSplit = 32;

  explicit PassSlicer(double slice_seconds, uint32_t max_batch = kMaxBatch)
      : slice_seconds_(slice_seconds), max_batch_(max_batch) {}

  // Renders the next slice of the pass under way, or the first slice of a new pass of batch()
  // samples; true when it completed the pass (counted with Renderer::finish_pass).
  bool render_slice(Renderer& renderer);
  bool render_slice(SliceTarget& target);

  bool in_pass() const { return next_pixel_ != 0; }
  uint32_t batch() const { return batch_; }
  // At most `most` (>= 1) samples in the next passes (a job's last pass ends at its spp).
  void limit_batch(uint32_t most);
  // A new view: no pass under way, one sample per pass; the cost measured so far stays (the
  // guess for the new view's pixels), the cost of each pixel is measured anew.
  void restart();
  // A new scene: restart(), and the cost is measured anew.
  void reset();

  // Measured slice by slice (a rising cost at once, a falling one smoothed); 0 until the first.
  double seconds_per_pixel_sample() const { return seconds_per_pixel_sample_; }
  // The last slice's pixel samples and device time (all its dispatches).
  double last_pixel_samples() const { return last_pixel_samples_; }
  double last_seconds() const { return last_seconds_; }

 private:
  // Pixels up to `end` (from the previous stretch's end) cost `cost` seconds a pixel sample.
  struct Stretch {
    uint64_t end;
    double cost;
  };
  // The next dispatch's pixels: `seconds` of the slice left, at most `most` pixels; 0: none
  // worth a dispatch (the first of a slice has one at least).
  uint64_t next_pixels(double seconds, uint64_t most, bool first, uint64_t first_pixels);
  // Pixels from next_pixel_, as many as the costs the last whole pass measured fit in `seconds`
  // (at most `most`).
  uint64_t proven_pixels(double seconds, uint64_t most);

  const double slice_seconds_;
  const uint32_t max_batch_;
  uint32_t batch_ = 1;
  uint64_t next_pixel_ = 0;  // of the pass under way, in row order
  double seconds_per_pixel_sample_ = 0;
  double largest_pixel_samples_ = 0;
  double last_pixel_samples_ = 0, last_seconds_ = 0;
  std::vector<Stretch> measured_;   // the last whole pass of this view, in row order
  std::vector<Stretch> measuring_;  // the pass under way
  size_t cursor_ = 0;               // the first stretch of measured_ past next_pixel_
};

}  // namespace geodesic
