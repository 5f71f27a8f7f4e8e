// The per-render uniform block and the push constants, defined once with the shaders
// (shaders/common/gpu_types.h).
#pragma once

#include "common/gpu_types.h"

namespace geodesic {

using gpu::FrameUniforms;  // the per-render uniform block (std140)
// Which samples one dispatch adds, to which pixels (the push constants): a pass over a large
// image is split into slices (render/service/pass_slicer.h).
using gpu::SampleRange;

}  // namespace geodesic
