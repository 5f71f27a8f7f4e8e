// The per-render uniform block (std140), mirrored by `Frame` in shaders/common/scene_data.glsl.
#pragma once

#include <array>
#include <cstdint>

namespace geodesic {

struct FrameUniforms {
  std::array<float, 16> camera_pose;  // column-major camera -> world isometry
  std::array<float, 4> ambient_light;
  float tan_half_fov_y;
  float aspect;
  uint32_t width;
  uint32_t height;
  uint32_t max_depth;
  uint32_t light_count;
  uint32_t seed;
  uint32_t russian_roulette;  // 0 or 1
  uint32_t max_crossings;     // cell faces a ray may cross
  uint32_t camera_cell;
  uint32_t lighting;        // 0 paper, 1 physical (LightingModel)
  uint32_t light_sampling;  // LightSampling: 0 MIS, 1 BSDF alone, 2 light sampling alone
  uint32_t emitter_count;
  float light_cutoff;       // geodesic distance (1e30: none)
  float clamp;              // largest sample luminance; 0: no clamp
  uint32_t padding;
};
static_assert(sizeof(FrameUniforms) == 144, "must match the std140 layout of Frame");

// Which samples one dispatch adds, to which pixels (push constants, mirrored by `Push` in
// shaders/common/scene_data.glsl): a pass over a large image is split into slices (bands of
// rows, or part of one row: render/pass_slicer.h), so that the render thread can turn to a
// camera move or to another session in between.
struct SampleRange {
  uint32_t start;
  uint32_t count;
  uint32_t column_offset = 0;
  uint32_t row_offset = 0;
  uint32_t column_count = 0;  // the dispatch's rectangle of pixels
  uint32_t row_count = 0;
};

}  // namespace geodesic
