// Cuts the passes of a progressive render into slices of about a given device time, so that
// whoever shares the device (the render thread's other sessions, a camera move, the render
// jobs) waits at most about one slice, whatever the scene costs: a pass adds batch() samples to
// every pixel, and a slice renders as many pixels of it, in row order, as the measured cost of
// a pixel sample fits in the slice: whole rows when a row fits, otherwise part of one row (a
// 1920-pixel row of a scene with a thousand lights can take seconds). A pass that fits in one
// slice in under half its time doubles the batch for the next (up to the slicer's largest
// batch), one that takes two slices' time halves it. The one scheduler of passes: the render
// service keeps one per session, a render job one for itself, and `geodesic render` one for
// its render (quarter-second passes: slices of half a second, batches up to 64).
#pragma once

#include <cstdint>

#include "render/device/renderer.h"

namespace geodesic {

class PassSlicer {
 public:
  static constexpr uint32_t kMaxBatch = 256;  // the default: larger passes are not faster
  // Pixels in the first slice, before the cost is known.
  static constexpr uint64_t kFirstPixels = 64;
  // A slice has at most this many times the pixel samples of the largest one so far, so that a
  // cost measured on cheap pixels (the sky) cannot size a slice of expensive ones far too long.
  static constexpr double kMaxGrowth = 4;

  explicit PassSlicer(double slice_seconds, uint32_t max_batch = kMaxBatch)
      : slice_seconds_(slice_seconds), max_batch_(max_batch) {}

  // Renders the next slice of the pass under way, or the first slice of a new pass of batch()
  // samples; true when it completed the pass (counted with Renderer::finish_pass).
  bool render_slice(Renderer& renderer);

  bool in_pass() const { return next_pixel_ != 0; }
  uint32_t batch() const { return batch_; }
  // At most `most` (>= 1) samples in the next passes (a job's last pass ends at its spp).
  void limit_batch(uint32_t most);
  // A new view: no pass under way, one sample per pass; the cost measured so far stays.
  void restart();
  // A new scene: restart(), and the cost is measured anew.
  void reset();

  // Measured, smoothed; 0 until the first slice.
  double seconds_per_pixel_sample() const { return seconds_per_pixel_sample_; }
  // The last slice's pixel samples and device time.
  double last_pixel_samples() const { return last_pixel_samples_; }
  double last_seconds() const { return last_seconds_; }

 private:
  PixelRegion next_region(const Renderer& renderer) const;

  const double slice_seconds_;
  const uint32_t max_batch_;
  uint32_t batch_ = 1;
  uint64_t next_pixel_ = 0;  // of the pass under way, in row order
  double seconds_per_pixel_sample_ = 0;
  double largest_pixel_samples_ = 0;
  double last_pixel_samples_ = 0, last_seconds_ = 0;
};

}  // namespace geodesic
