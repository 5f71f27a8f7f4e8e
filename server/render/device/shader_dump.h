// `geodesic render --dump-shaders DIR`: the GLSL (preprocessed: the scene's defines applied,
// includes resolved) and the SPIR-V of every shader in a renderer's pipeline, and the
// features that chose them, for reading what a scene actually runs.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "render/device/renderer.h"

namespace geodesic {

// Writes DIR/<entry>.glsl and DIR/<entry>.spv per entry point (e.g. ray_query.comp.glsl) and
// DIR/features.txt; returns the files written.
std::vector<std::filesystem::path> dump_shaders(const Renderer& renderer,
                                                const std::filesystem::path& dir);

}  // namespace geodesic
