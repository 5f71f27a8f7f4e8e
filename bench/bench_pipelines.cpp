// What per-scene pipelines buy (docs/benchmarks.md, "Specialised pipelines"): for each bundled
// scene, the pipeline build time cold (glslang + driver), from the pipeline cache's directory
// (a restarted daemon) and from memory (a second session), the SPIR-V size, and paths/s, each
// for the scene's specialised pipeline and for the all-features one, measured in one run.
//   geodesic_bench_pipelines [SCENE.json ...] [--size N] [--seconds S] [--repeat R]
//                            [--device SEL] [--backend auto|ray-query|pipeline]
// Mesa's own shader cache is turned off, so that cold means cold: the figures are this
// project's cache alone.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "render/device/pipeline_cache.h"
#include "render/device/renderer.h"
#include "scene/scene_loader.h"

using namespace geodesic;
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Options {
  std::vector<std::string> scenes;
  int size = 128;
  double seconds = 1.0;  // per paths/s measurement
  int repeat = 3;
  std::string device, backend = "auto";
};

struct Builds {
  double cold = 0, disk = 0, memory = 0;  // seconds
  size_t spirv_bytes = 0;
};

// Cold: nothing cached. Disk: memory dropped, the directory kept (a restarted daemon). Memory:
// a second renderer on the same device (a second session).
Builds measure_builds(VulkanContext& ctx, const Scene& scene, BackendKind backend,
                      PipelineVariant variant, const fs::path& dir) {
  PipelineCache& cache = ctx.pipeline_cache();
  Builds b;
  cache.set_directory({});
  cache.forget_pipelines();
  {
    Renderer r(ctx, scene, backend, variant);
    b.cold = r.backend().pipeline().build_seconds;
    b.spirv_bytes = r.backend().pipeline().spirv_bytes;
  }
  cache.forget_pipelines();
  fs::remove_all(dir);
  cache.set_directory(dir);
  { Renderer fill(ctx, scene, backend, variant); }  // writes the directory
  cache.forget_pipelines();
  {
    Renderer r(ctx, scene, backend, variant);
    b.disk = r.backend().pipeline().build_seconds;
    const uint64_t builds = cache.stats().pipeline_builds;
    const auto start = Clock::now();
    Renderer second(ctx, scene, backend, variant);
    b.memory = since(start);  // the whole second renderer: scene upload included
    if (cache.stats().pipeline_builds != builds)
      throw std::runtime_error("a second renderer rebuilt its pipeline");
  }
  cache.set_directory({});
  return b;
}

// Paths/s of the two variants, interleaved run by run (best of `repeat`), so that a busy
// moment on the machine hurts both alike.
std::pair<double, double> measure_speed(VulkanContext& ctx, const Scene& scene,
                                        BackendKind backend, const Options& o) {
  Renderer specialised(ctx, scene, backend, PipelineVariant::Specialised);
  Renderer all(ctx, scene, backend, PipelineVariant::AllFeatures);
  const double pixels = double(scene.render.width) * scene.render.height;
  // Samples per run: about `seconds` of the specialised pipeline.
  specialised.add_samples(1);
  all.add_samples(1);
  auto start = Clock::now();
  specialised.add_samples(1);
  const uint32_t spp = uint32_t(std::clamp(o.seconds / std::max(since(start), 1e-4), 1.0, 1024.0));
  double best[2] = {0, 0};
  for (int r = 0; r < o.repeat; ++r) {
    Renderer* renderers[2] = {&specialised, &all};
    for (int v = 0; v < 2; ++v) {
      renderers[v]->reset();
      start = Clock::now();
      renderers[v]->add_samples(spp);
      best[v] = std::max(best[v], spp * pixels / since(start));
    }
  }
  return {best[0], best[1]};
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&] {
      if (i + 1 >= argc) throw std::invalid_argument(a + ": needs a value");
      return std::string(argv[++i]);
    };
    if (a == "--size") o.size = std::stoi(value());
    else if (a == "--seconds") o.seconds = std::stod(value());
    else if (a == "--repeat") o.repeat = std::stoi(value());
    else if (a == "--device") o.device = value();
    else if (a == "--backend") o.backend = value();
    else o.scenes.push_back(a);
  }
  if (o.scenes.empty()) {
    for (const auto& e : fs::directory_iterator(fs::path(GEODESIC_SOURCE_DIR) / "scenes"))
      if (e.path().extension() == ".json") o.scenes.push_back(e.path().string());
    std::sort(o.scenes.begin(), o.scenes.end());
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    VulkanContext ctx(o.device);
    const BackendKind backend = resolve_backend(parse_backend(o.backend), ctx.description());
    const fs::path dir = fs::temp_directory_path() / "geodesic-bench-pipelines";
    std::printf("%dx%d, about %.1f s per run, best of %d, %s back end, device %s\n\n", o.size,
                o.size, o.seconds, o.repeat,
                backend == BackendKind::RayQuery ? "ray-query" : "pipeline",
                ctx.description().name.c_str());
    {  // the first build in a process also sets glslang up: keep that out of the figures
      Scene warm = load_scene_file(o.scenes.front());
      Renderer warm_up(ctx, warm, backend);
    }
    std::printf("| scene | specialised for | SPIR-V KiB (spec / all) | cold build s (spec / all) "
                "| from disk s | 2nd session s | M paths/s (spec / all) | speed-up |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string& path : o.scenes) {
      Scene scene = load_scene_file(path);
      scene.render.width = scene.render.height = o.size;
      const Builds spec = measure_builds(ctx, scene, backend, PipelineVariant::Specialised, dir);
      const Builds all = measure_builds(ctx, scene, backend, PipelineVariant::AllFeatures, dir);
      const auto [fast, slow] = measure_speed(ctx, scene, backend, o);
      const PipelineFeatures features = Renderer(ctx, scene, backend).features();
      std::printf("| %s | %s | %zu / %zu | %.2f / %.2f | %.3f | %.3f | %.3f / %.3f | %.2fx |\n",
                  fs::path(path).stem().c_str(), features.summary().c_str(),
                  spec.spirv_bytes / 1024, all.spirv_bytes / 1024, spec.cold, all.cold,
                  spec.disk, spec.memory, fast / 1e6, slow / 1e6, fast / slow);
      std::fflush(stdout);
    }
    fs::remove_all(dir);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "geodesic_bench_pipelines: %s\n", e.what());
    return 1;
  }
  return 0;
}
