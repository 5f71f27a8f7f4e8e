// The scene document's "render" object (docs/scene-format.md): image size, depth, samples,
// lighting model, light sampling, exposure.
#pragma once

#include "scene/json_path.h"
#include "scene/scene.h"

namespace geodesic {

RenderSettings read_render(const JsonNode& node);

// Stops (a number in [-20, 20]) or "auto" (render/prepare/exposure.h); the scene's, a `settings`
// message's and a render job's exposure. Throws std::invalid_argument with the reason.
Exposure exposure_from_json(const nlohmann::ordered_json& value);
nlohmann::ordered_json exposure_to_json(const Exposure& exposure);

}  // namespace geodesic
