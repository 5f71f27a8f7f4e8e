#include "render/device/renderer.h"

#include <stdexcept>
#include <string>

#include "render/prepare/accumulation_file.h"
#include "render/prepare/relative_error.h"
#include "scene/scene_isometry.h"

namespace geodesic {
namespace {

// How far the camera may go from the frame's centre before a new frame pays: float keeps about
// u e^(2 r) of a direction in H3 (3e-6 at r = 2), and u r of a position in E3.
double frame_reach(GeometryKind k) { return k == GeometryKind::Hyperbolic ? 2 : 100; }

bool without_quotient(GeometryKind k, const std::vector<Cell>& cells) {
  return k != GeometryKind::Spherical && cells.size() == 1 && cells[0].faces.empty();
}

}  // namespace

Renderer::Renderer(VulkanContext& ctx, const Scene& scene, BackendKind backend,
                   PipelineVariant variant)
    : ctx_(ctx),
      geometry_(scene.geometry),
      cells_(build_cells(scene)),
      camera_relative_(without_quotient(geometry_, cells_)),
      into_frame_(camera_relative_ ? WideIsometry(geometry_, scene.camera.pose).inverse()
                                   : WideIsometry(geometry_, Mat4::identity())),
      resources_(ctx, camera_relative_ ? moved_scene(scene, into_frame_) : scene, variant),
      backend_(make_backend(backend, ctx, resources_)) {}

void Renderer::add_samples(uint32_t samples) {
  render_region(samples, {0, 0, uint32_t(width()), uint32_t(height())});
  finish_pass(samples);
}

void Renderer::render_region(uint32_t samples, const PixelRegion& region) {
  if (samples == 0 || region.columns == 0 || region.rows == 0) return;
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    backend_->record(cmd, SampleRange{samples_, samples, region.column, region.row,
                                      region.columns, region.rows});
  });
}

void Renderer::reset() {
  resources_.clear_accumulation();
  samples_ = 0;
}

Mat4 Renderer::set_view(const Mat4& camera_pose, int width, int height) {
  if (!camera_relative_) {
    const CameraPlacement placed = place_camera(geometry_, cells_, camera_pose);
    resources_.set_view(placed.pose, placed.cell, uint32_t(width), uint32_t(height));
    samples_ = 0;
    return placed.pose;
  }
  resources_.set_view(into_frame_.apply(camera_pose), 0, uint32_t(width), uint32_t(height));
  samples_ = 0;
  return model::reorthonormalize(geometry_, camera_pose);
}

bool Renderer::frame_outgrown(const Mat4& camera_pose) const {
  if (!camera_relative_) return false;
  const Vec4 seen = into_frame_.apply(camera_pose * model::origin());
  return model::geodesic_distance(geometry_, model::origin(), seen) > frame_reach(geometry_);
}

void Renderer::set_sampling(int max_depth, int light_samples) {
  resources_.set_sampling(uint32_t(max_depth), light_samples);
  samples_ = 0;
}

std::span<const float> Renderer::accumulation() const {
  return {resources_.accumulation(), size_t(2) * width() * height() * 4};
}

void Renderer::restore(uint32_t samples, std::span<const float> sums) {
  if (sums.size() != accumulation().size())
    throw std::invalid_argument("checkpoint: " + std::to_string(sums.size()) +
                                " floats for a view of " + std::to_string(accumulation().size()));
  resources_.load_accumulation(sums.data());
  samples_ = samples;
}

Image Renderer::image() const {
  const float* even = resources_.accumulation();
  return mean_image(even, even + size_t(width()) * height() * 4, width(), height());
}

double Renderer::estimated_error() const {
  const size_t pixels = size_t(width()) * height();
  const float* even = resources_.accumulation();
  return estimated_relative_rmse(even, even + pixels * 4, pixels);
}

}  // namespace geodesic
