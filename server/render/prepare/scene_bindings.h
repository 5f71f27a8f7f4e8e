// Descriptor binding numbers of shaders/common/scene_data.glsl, from shaders/common/bindings.h
// (their one definition): one set, one binding per buffer (and the acceleration structure). A
// specialised pipeline declares only the bindings its shaders read (PipelineFeatures::bindings).
#pragma once

#include <cstdint>

#include "common/bindings.h"

namespace geodesic {

enum SceneBinding : uint32_t {
  kSceneBinding = BINDING_SCENE,
  kAccumulationBinding = BINDING_ACCUMULATION,
  kFrameBinding = BINDING_FRAME,
  kSpheresBinding = BINDING_SPHERES,
  kMaterialsBinding = BINDING_MATERIALS,
  kLightsBinding = BINDING_LIGHTS,
  kPositionsBinding = BINDING_POSITIONS,
  kNormalsBinding = BINDING_NORMALS,
  kIndicesBinding = BINDING_INDICES,
  kTrianglesBinding = BINDING_TRIANGLES,
  kRayCountsBinding = BINDING_RAY_COUNTS,
  kSphereRefsBinding = BINDING_SPHERE_REFS,
  kCellsBinding = BINDING_CELLS,
  kCellFacesBinding = BINDING_CELL_FACES,
  kDiagnosticsBinding = BINDING_DIAGNOSTICS,
  kEmittersBinding = BINDING_EMITTERS,
  kLightImagesBinding = BINDING_LIGHT_IMAGES,
  kTubesBinding = BINDING_TUBES,
  kShapesBinding = BINDING_SHAPES,
  kShapeRefsBinding = BINDING_SHAPE_REFS,
  kListedBinding = BINDING_LISTED,
  kSceneBindingCount = BINDING_COUNT
};

}  // namespace geodesic
