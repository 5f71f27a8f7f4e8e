#include "render/service/pass_slicer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace geodesic {

double SliceTarget::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

namespace {

class RendererTarget final : public SliceTarget {
 public:
  explicit RendererTarget(Renderer& renderer) : renderer_(renderer) {}
  int width() const override { return renderer_.width(); }
  int height() const override { return renderer_.height(); }
  void render_region(uint32_t samples, const PixelRegion& region) override {
    renderer_.render_region(samples, region);
  }
  void finish_pass(uint32_t samples) override { renderer_.finish_pass(samples); }
  double parallel_pixel_samples() const override {
    return renderer_.context().description().cpu ? 1 : PassSlicer::kGpuParallelPixelSamples;
  }

 private:
  Renderer& renderer_;
};

// `pixels` (>= 1) from `first` in row order as one rectangle: whole rows from a row's start
// when there is a row's worth, otherwise part of one row.
PixelRegion row_order(uint64_t first, uint64_t pixels, uint64_t width) {
  const auto row = uint32_t(first / width), column = uint32_t(first % width);
  if (column == 0 && pixels >= width) return {0, row, uint32_t(width), uint32_t(pixels / width)};
  return {column, row, uint32_t(std::min<uint64_t>(pixels, width - column)), 1};
}

}  // namespace

bool PassSlicer::render_slice(Renderer& renderer) {
  RendererTarget target(renderer);
  return render_slice(target);
}

uint64_t PassSlicer::proven_pixels(double seconds, uint64_t most) {
  while (cursor_ < measured_.size() && measured_[cursor_].end <= next_pixel_) ++cursor_;
  const uint64_t last = next_pixel_ + most;
  uint64_t at = next_pixel_;
  for (size_t i = cursor_; i < measured_.size() && at < last; ++i) {
    const double per_pixel = measured_[i].cost * batch_;
    const uint64_t span = std::min(measured_[i].end, last) - at;
    if (per_pixel * double(span) > seconds) return at - next_pixel_ + uint64_t(seconds / per_pixel);
    seconds -= per_pixel * double(span);
    at += span;
  }
  return at - next_pixel_;
}

uint64_t PassSlicer::next_pixels(double seconds, uint64_t most, bool first,
                                 uint64_t first_pixels) {
  if (largest_pixel_samples_ == 0) return std::min(first_pixels, most);  // nothing measured yet
  uint64_t pixels = 0;
  if (!measured_.empty()) {
    pixels = proven_pixels(seconds, most);
  } else {
    // A guess: the cost of the pixels just before in row order (at a pass's start, the cost
    // measured so far). Small dispatches, so that a guess far too low costs one of them, not the
    // slice; but first_pixels at least (a dispatch of a few pixels leaves the device's threads
    // idle), unless even those do not fit.
    const double guess = measuring_.empty() ? seconds_per_pixel_sample_ : measuring_.back().cost;
    const double per_pixel = guess * batch_;
    const auto fit = [&](double s) { return uint64_t(std::min(s / per_pixel, double(most))); };
    pixels = std::max(fit(std::min(seconds, slice_seconds_ / kUnprovenSplit)),
                      std::min(first_pixels, fit(seconds)));
  }
  // A slice renders a pixel at least, however dear: the pass goes on.
  return std::clamp<uint64_t>(pixels, first ? 1 : 0, most);
}

bool PassSlicer::render_slice(SliceTarget& target) {
  const uint64_t width = uint64_t(target.width());
  const uint64_t total = width * uint64_t(target.height());
  const bool whole_pass = next_pixel_ == 0;
  // The last pass's costs are this pass's only if they cover its pixels (restart() clears them
  // for a new view; a size changed without one is a new view too).
  if (whole_pass && !measured_.empty() && measured_.back().end != total) measured_.clear();
  // A dispatch's cost is counted over the device's parallel width at least, as it takes about
  // as long: otherwise a GPU's small dispatches, timed by one thread's path, would make every
  // pixel look dear, the next dispatches small, and so on (a walk at 1 frame/s, 80 px wide).
  const double parallel = std::max(target.parallel_pixel_samples(), 1.0);
  const uint64_t first_pixels = std::max(kFirstPixels, uint64_t(std::ceil(parallel / batch_)));
  // The slice's pixel samples, at most: first_pixels until a cost is measured.
  const double most = largest_pixel_samples_ > 0 ? kMaxGrowth * largest_pixel_samples_
                                                 : double(first_pixels) * batch_;
  const double start = target.seconds();
  double spent = 0, samples = 0, counted = 0;
  for (bool first = true;; first = false) {
    const uint64_t room = uint64_t(std::max((most - samples) / batch_, first ? 1.0 : 0.0));
    const uint64_t pixels =
        next_pixels(slice_seconds_ - spent, std::min(room, total - next_pixel_), first, first_pixels);
    if (pixels == 0) break;
    const PixelRegion region = row_order(next_pixel_, pixels, width);
    const double before = target.seconds();
    target.render_region(batch_, region);
    const double after = target.seconds();
    const uint64_t rendered = uint64_t(region.columns) * region.rows;
    const double dispatched = std::max(double(rendered) * batch_, parallel);
    measuring_.push_back({next_pixel_ + rendered, (after - before) / dispatched});
    next_pixel_ += rendered;
    samples += double(rendered) * batch_;
    counted += dispatched;
    spent = after - start;
    // The clock check: another dispatch only while a worthwhile one fits, in time (that of a
    // dispatch of guessed pixels) and in pixel samples (first_pixels).
    if (next_pixel_ == total || slice_seconds_ - spent < slice_seconds_ / kUnprovenSplit ||
        most - samples < double(first_pixels) * batch_)
      break;
  }
  last_seconds_ = spent;
  last_pixel_samples_ = samples;
  largest_pixel_samples_ = std::max(largest_pixel_samples_, last_pixel_samples_);
  // A rising cost is adopted at once: it sizes a new view's first dispatch, and one too low
  // overruns. A falling one is smoothed.
  const double cost = spent / counted;
  seconds_per_pixel_sample_ =
      cost > seconds_per_pixel_sample_ ? cost : 0.7 * seconds_per_pixel_sample_ + 0.3 * cost;

  if (next_pixel_ < total) return false;
  target.finish_pass(batch_);
  next_pixel_ = 0;
  measured_ = std::move(measuring_);  // every pixel's cost, for the next pass
  measuring_.clear();
  cursor_ = 0;
  if (whole_pass) {  // the pass fit in one slice: size the next one to the slice
    if (last_seconds_ < slice_seconds_ / 2) batch_ = std::min(2 * batch_, max_batch_);
    else if (last_seconds_ > slice_seconds_ * 2 && batch_ > 1) batch_ /= 2;
  }
  return true;
}

void PassSlicer::limit_batch(uint32_t most) { batch_ = std::clamp(batch_, 1u, std::max(most, 1u)); }

void PassSlicer::restart() {
  batch_ = 1;
  next_pixel_ = 0;
  measured_.clear();
  measuring_.clear();
  cursor_ = 0;
}

void PassSlicer::reset() {
  restart();
  seconds_per_pixel_sample_ = largest_pixel_samples_ = 0;
}

}  // namespace geodesic
