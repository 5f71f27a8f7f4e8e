#include "render/service/pass_slicer.h"

#include <algorithm>
#include <chrono>

namespace geodesic {

PixelRegion PassSlicer::next_region(const Renderer& renderer) const {
  const uint64_t width = uint64_t(renderer.width());
  const uint64_t rest = width * uint64_t(renderer.height()) - next_pixel_;
  double fits = double(kFirstPixels) * batch_;  // pixel samples
  if (seconds_per_pixel_sample_ > 0)
    fits = std::min(slice_seconds_ / seconds_per_pixel_sample_, kMaxGrowth * largest_pixel_samples_);
  const uint64_t pixels = std::clamp<uint64_t>(uint64_t(fits / batch_), 1, rest);
  const auto row = uint32_t(next_pixel_ / width), column = uint32_t(next_pixel_ % width);
  if (column == 0 && pixels >= width)  // whole rows
    return {0, row, uint32_t(width), uint32_t(pixels / width)};
  return {column, row, uint32_t(std::min<uint64_t>(pixels, width - column)), 1};  // part of a row
}

bool PassSlicer::render_slice(Renderer& renderer) {
  const PixelRegion region = next_region(renderer);
  const auto start = std::chrono::steady_clock::now();
  renderer.render_region(batch_, region);
  last_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const uint64_t pixels = uint64_t(region.columns) * region.rows;
  last_pixel_samples_ = double(pixels) * batch_;
  largest_pixel_samples_ = std::max(largest_pixel_samples_, last_pixel_samples_);
  const double cost = last_seconds_ / last_pixel_samples_;
  seconds_per_pixel_sample_ =
      seconds_per_pixel_sample_ > 0 ? 0.7 * seconds_per_pixel_sample_ + 0.3 * cost : cost;

  const bool whole_pass = next_pixel_ == 0;
  next_pixel_ += pixels;
  if (next_pixel_ < uint64_t(renderer.width()) * uint64_t(renderer.height())) return false;
  renderer.finish_pass(batch_);
  next_pixel_ = 0;
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
}

void PassSlicer::reset() {
  restart();
  seconds_per_pixel_sample_ = largest_pixel_samples_ = 0;
}

}  // namespace geodesic
