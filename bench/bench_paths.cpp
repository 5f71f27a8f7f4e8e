// Throughput of the path tracer on a scene (default: the bundled Cornell box at 512x512,
// depth 5): paths/s and rays/s for each tracing back end the device offers, measured in the
// same run, with their ratio.
//   geodesic_bench [SCENE.json] [--spp N] [--device SEL] [--repeat R] [--russian-roulette]
//                  [--geometry euclidean|hyperbolic|spherical] [--size N]
// --geometry renders the same scene document in another model geometry (its coordinates read
// as exponential coordinates there): the cost of curvature on a comparable scene.
//   geodesic_bench --quotients [SCENE.json ...] [--size N] [--spp N] [--repeat R]
// measures the Cornell box and the quotient scenes (default: the bundled ones and a lens and a
// Coxeter space of the catalogue), each at its own depth, with the auto back end, in one run of
// R paired rounds (each scene's run beside one of the Cornell box): median paths/s, the
// device's counters (chart segments traced per path, face crossings per segment, segments cut
// off at max_crossings) and the median and range of the ratio to the Cornell box.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "render/device/renderer.h"
#include "scene/scene_loader.h"

using namespace geodesic;

namespace {

struct Measurement {
  double paths_per_second = 0;
  double rays_per_second = 0;
  double paths = 0;
  TraceCounters counters;  // of the best run
};

// Seconds for one run of `spp` samples (the accumulation reset first). A run is one dispatch
// of all its samples, as the service's slices hold many: a dispatch per sample measured a GPU's
// submissions (the Cornell box on an H200: 0.3 ms of work behind each), not its paths.
double timed_run(Renderer& renderer, uint32_t spp) {
  renderer.reset();
  const auto start = std::chrono::steady_clock::now();
  renderer.add_samples(spp);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double paths_of(const Scene& scene, uint32_t spp) {
  return double(spp) * scene.render.width * scene.render.height;
}

// Best of `repeat` timed runs (after a warm-up sample that also compiles the pipeline): the
// least-disturbed run is the fairest figure on a shared 2-core machine.
Measurement measure(VulkanContext& ctx, const Scene& scene, BackendKind backend, uint32_t spp,
                    int repeat) {
  Renderer renderer(ctx, scene, backend);
  renderer.add_samples(1);
  Measurement best;
  for (int r = 0; r < repeat; ++r) {
    const double seconds = timed_run(renderer, spp);
    const double paths = paths_of(scene, spp);
    if (paths / seconds > best.paths_per_second)
      best = {paths / seconds, double(renderer.traced_rays()) / seconds, paths,
              renderer.trace_counters()};
  }
  return best;
}

Scene load_for_bench(const std::string& path, int size, bool russian_roulette) {
  Scene scene = load_scene_file(path);
  // Full depth unless asked: the physical model's own default would end paths early.
  scene.render.russian_roulette = russian_roulette;
  if (size > 0) scene.render.width = scene.render.height = size;
  return scene;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The Cornell box and each scene, at its own depth, with the auto back end, in `rounds` paired
// rounds: in each, every scene runs right beside a run of the Cornell box (before it in even
// rounds, after it in odd ones), and its ratio is that pair's. A shared machine's speed drifts
// by tens of percent over a minute; a pair's two runs, a second or two apart, see the same
// machine. Printed: the median paths/s, the median ratio and the ratios' range.
int quotient_table(std::vector<std::string> scenes, const std::string& device, int size,
                   uint32_t spp, int rounds) {
  const std::string dir = std::string(GEODESIC_SOURCE_DIR) + "/scenes/";
  if (scenes.empty())
    for (const char* name :
         {"mirrored-dodecahedron", "seifert-weber", "poincare-sphere", "torus-cornell",
          "quarter-turn-space", "catalogue/lens-7-3", "catalogue/coxeter-5-3-4",
          "figure-eight-knot", "whitehead-link"})
      scenes.push_back(dir + name + ".json");
  scenes.insert(scenes.begin(), dir + "cornell-box.json");
  rounds = std::max(rounds, 1);
  VulkanContext ctx(device);
  std::printf("%u spp per run, %d paired rounds, device %s\n", spp, rounds,
              ctx.description().name.c_str());
  struct Row {
    std::string path;
    Scene scene;
    std::unique_ptr<Renderer> renderer;
    std::vector<double> rates, ratios;
  };
  std::vector<Row> rows;
  for (const std::string& path : scenes) {
    Row row{path, load_for_bench(path, size, false), nullptr, {}, {}};
    row.renderer = std::make_unique<Renderer>(ctx, row.scene, BackendKind::Auto);
    row.renderer->add_samples(1);  // compiles the pipeline, warms the caches
    rows.push_back(std::move(row));
  }
  Row& cornell = rows.front();
  const auto paths_per_second = [spp](Row& row) {
    return paths_of(row.scene, spp) / timed_run(*row.renderer, spp);
  };
  for (int round = 0; round < rounds; ++round)
    for (size_t i = 1; i < rows.size(); ++i) {
      const bool cornell_first = round % 2 == 0;
      const double before = cornell_first ? paths_per_second(cornell) : 0;
      const double rate = paths_per_second(rows[i]);
      const double base = cornell_first ? before : paths_per_second(cornell);
      cornell.rates.push_back(base);
      rows[i].rates.push_back(rate);
      rows[i].ratios.push_back(rate / base);
    }
  cornell.ratios = {1.0};
  std::printf("%-24s %5s %9s %7s %9s %9s %10s %9s %11s\n", "scene", "depth", "size", "M p/s",
              "segs/path", "cross/geo", "truncated", "x Cornell", "range");
  for (Row& row : rows) {
    // The device's counters of the last run. Each traced segment is one traversal; a geodesic
    // is its first segment and one more per face crossed; truncated: geodesics cut off at
    // max_crossings, per geodesic.
    const TraceCounters counters = row.renderer->trace_counters();
    const double paths = paths_of(row.scene, spp);
    const double segments = double(counters.traced_rays);
    const double geodesics = std::max(segments - double(counters.crossed_faces), 1.0);
    const auto [low, high] = std::minmax_element(row.ratios.begin(), row.ratios.end());
    const std::string stem = row.path.substr(row.path.find_last_of('/') + 1);
    std::printf("%-24s %5d %4dx%-4d %7.4f %9.2f %9.2f %10.2e %9.3f %5.3f-%5.3f\n",
                stem.substr(0, stem.size() - 5).c_str(), row.scene.render.max_depth,
                row.scene.render.width, row.scene.render.height, median(row.rates) / 1e6,
                segments / paths, double(counters.crossed_faces) / geodesics,
                double(counters.truncated_rays) / geodesics, median(row.ratios), *low, *high);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_path = std::string(GEODESIC_SOURCE_DIR) + "/scenes/cornell-box.json";
  std::string device;
  uint32_t spp = 16;
  int repeat = 3;
  bool russian_roulette = false, quotients = false;
  int size = 0;
  std::vector<std::string> scenes;
  std::string geometry, lighting;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--spp" && i + 1 < argc) spp = std::stoul(argv[++i]);
    else if (a == "--device" && i + 1 < argc) device = argv[++i];
    else if (a == "--repeat" && i + 1 < argc) repeat = std::stoi(argv[++i]);
    else if (a == "--russian-roulette") russian_roulette = true;
    else if (a == "--geometry" && i + 1 < argc) geometry = argv[++i];
    else if (a == "--lighting" && i + 1 < argc) lighting = argv[++i];
    else if (a == "--size" && i + 1 < argc) size = std::stoi(argv[++i]);
    else if (a == "--quotients") quotients = true;
    else scenes.push_back(scene_path = a);
  }
  try {
    if (quotients) return quotient_table(scenes, device, size, spp, repeat);
    Scene scene = load_for_bench(scene_path, size, russian_roulette);
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
