// `geodesic render --report FILE.json`: what a render did and how its estimated error fell,
// as JSON (FILE.json) and the series alone as CSV next to it (FILE.csv).
#pragma once

#include <filesystem>
#include <string>

#include "render/prepare/convergence.h"

namespace geodesic {

struct RenderReport {
  std::string scene, geometry, device, backend;
  int width = 0, height = 0;
  uint32_t samples = 0;
  double seconds = 0;
  double estimated_error = -1;  // negative while unknown: written as null
  StopCondition stop;
  std::string stopped_by;  // StopCondition::met's name of the condition that ended the render
  ConvergenceLog log;
  // Samples whose value was NaN or infinite (dropped, counted as black), and geodesics cut off
  // at the scene's crossing bound (they return black: docs/numerics.md).
  uint64_t non_finite_samples = 0;
  uint64_t truncated_geodesics = 0;
};

// Writes `json_path` and the CSV with the same stem; throws std::runtime_error naming the file
// it could not write.
void write_render_report(const std::filesystem::path& json_path, const RenderReport& report);

}  // namespace geodesic
