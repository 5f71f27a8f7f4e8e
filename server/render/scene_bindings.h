// Descriptor binding numbers of shaders/common/scene_data.glsl: one set, one binding per
// buffer (and the acceleration structure). A specialised pipeline declares only the bindings
// its shaders read (PipelineFeatures::bindings).
#pragma once

#include <cstdint>

namespace geodesic {

enum SceneBinding : uint32_t {
  kSceneBinding = 0, kAccumulationBinding, kFrameBinding, kSpheresBinding, kMaterialsBinding,
  kLightsBinding, kPositionsBinding, kNormalsBinding, kIndicesBinding, kTrianglesBinding,
  kRayCountsBinding, kSphereRefsBinding, kCellsBinding, kCellFacesBinding, kDiagnosticsBinding,
  kEmittersBinding, kLightImagesBinding, kTubesBinding, kSceneBindingCount
};

}  // namespace geodesic
