// Throughput of the path tracer on a scene (default: the bundled Cornell box at 512x512,
// depth 5): paths/s and rays/s for each tracing back end the device offers, measured in the
// same run, with their ratio.
//   geodesic_bench [SCENE.json] [--spp N] [--device SEL] [--repeat R] [--russian-roulette]
//                  [--geometry euclidean|hyperbolic|spherical]
// --geometry renders the same scene document in another model geometry (its coordinates read
// as exponential coordinates there): the cost of curvature on a comparable scene.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "render/renderer.h"
#include "scene/scene_loader.h"

using namespace geodesic;

namespace {

struct Measurement {
  double paths_per_second = 0;
  double rays_per_second = 0;
};

// Best of `repeat` timed runs (after a warm-up sample that also compiles the pipeline): the
// least-disturbed run is the fairest figure on a shared 2-core machine.
Measurement measure(VulkanContext& ctx, const Scene& scene, BackendKind backend, uint32_t spp,
                    int repeat) {
  Renderer renderer(ctx, scene, backend);
  renderer.add_samples(1);
  Measurement best;
  for (int r = 0; r < repeat; ++r) {
    renderer.reset();
    const auto start = std::chrono::steady_clock::now();
    for (uint32_t s = 0; s < spp; ++s) renderer.add_samples(1);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double paths = double(spp) * scene.render.width * scene.render.height;
    if (paths / seconds > best.paths_per_second)
      best = {paths / seconds, double(renderer.traced_rays()) / seconds};
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_path = std::string(GEODESIC_SOURCE_DIR) + "/scenes/cornell-box.json";
  std::string device;
  uint32_t spp = 16;
  int repeat = 3;
  bool russian_roulette = false;
  std::string geometry, lighting;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--spp" && i + 1 < argc) spp = std::stoul(argv[++i]);
    else if (a == "--device" && i + 1 < argc) device = argv[++i];
    else if (a == "--repeat" && i + 1 < argc) repeat = std::stoi(argv[++i]);
    else if (a == "--russian-roulette") russian_roulette = true;
    else if (a == "--geometry" && i + 1 < argc) geometry = argv[++i];
    else if (a == "--lighting" && i + 1 < argc) lighting = argv[++i];
    else scene_path = a;
  }
  try {
    Scene scene = load_scene_file(scene_path);
    // Full depth unless asked: the physical model's own default would end paths early.
    scene.render.russian_roulette = russian_roulette;
    if (lighting == "paper") scene.render.lighting = LightingModel::Paper;
    if (lighting == "physical") scene.render.lighting = LightingModel::Physical;
    for (GeometryKind kind :
         {GeometryKind::Euclidean, GeometryKind::Hyperbolic, GeometryKind::Spherical})
      if (geometry == geometry_name(kind)) scene.geometry = kind;
    VulkanContext ctx(device);
    std::printf("scene %s (%s, %s model), %dx%d, depth %d%s, %u spp per run, best of %d, device %s\n",
                scene_path.c_str(), geometry_name(scene.geometry),
                scene.render.lighting == LightingModel::Paper ? "paper" : "physical",
                scene.render.width,
                scene.render.height,
                scene.render.max_depth,
                scene.render.russian_roulette ? " with Russian roulette" : "", spp, repeat,
                ctx.description().name.c_str());
    std::vector<std::pair<std::string, Measurement>> results;
    if (ctx.description().ray_query)
      results.emplace_back("ray-query", measure(ctx, scene, BackendKind::RayQuery, spp, repeat));
    if (ctx.description().ray_tracing_pipeline)
      results.emplace_back("pipeline",
                           measure(ctx, scene, BackendKind::RayTracingPipeline, spp, repeat));
    const double baseline = results.back().second.paths_per_second;
    for (const auto& [name, m] : results)
      std::printf("%-10s %8.3f M paths/s %8.3f M rays/s  %.2fx of %s\n", name.c_str(),
                  m.paths_per_second / 1e6, m.rays_per_second / 1e6,
                  m.paths_per_second / baseline, results.back().first.c_str());
    std::printf("auto back end on this device: %s\n",
                resolve_backend(BackendKind::Auto, ctx.description()) == BackendKind::RayQuery
                    ? "ray-query"
                    : "pipeline");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "geodesic_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
