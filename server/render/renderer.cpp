#include "render/renderer.h"

namespace geodesic {

Renderer::Renderer(VulkanContext& ctx, const Scene& scene, BackendKind backend)
    : ctx_(ctx), resources_(ctx, scene), backend_(make_backend(backend, ctx, resources_)) {}

void Renderer::add_samples(uint32_t samples) {
  if (samples == 0) return;
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    backend_->record(cmd, SampleRange{samples_, samples});
  });
  samples_ += samples;
}

void Renderer::reset() {
  resources_.clear_accumulation();
  samples_ = 0;
}

Image Renderer::image() const {
  Image image;
  image.width = static_cast<int>(resources_.width());
  image.height = static_cast<int>(resources_.height());
  const size_t pixels = size_t(image.width) * image.height;
  image.rgb.resize(pixels * 3);
  const float* sums = resources_.accumulation();
  for (size_t p = 0; p < pixels; ++p) {
    const float count = sums[p * 4 + 3];
    for (int c = 0; c < 3; ++c) image.rgb[p * 3 + c] = count > 0 ? sums[p * 4 + c] / count : 0;
  }
  return image;
}

}  // namespace geodesic
