// `geodesic render SCENE.json -o OUT.{png,exr,jpg}`: renders one view to a file, in passes
// scheduled by the daemon's PassSlicer, until the stop condition (--spp, --time or
// --target-error) is met; optionally a sample-parallel part (--samples-from, --accumulation)
// and a report of the convergence series (--report).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/progress_bar.h"
#include "cli/render_report.h"
#include "render/prepare/accumulation_file.h"
#include "render/prepare/convergence.h"
#include "render/prepare/exposure.h"
#include "render/prepare/image_io.h"
#include "render/service/pass_slicer.h"
#include "render/device/pipeline_cache.h"
#include "render/device/renderer.h"
#include "render/device/shader_dump.h"
#include "scene/scene_source.h"

namespace geodesic {
namespace {

// A pass that takes under a quarter second (half a slice) doubles the next, up to 64 samples.
constexpr double kCliSliceSeconds = 0.5;
constexpr uint32_t kCliMaxBatch = 64;

struct RenderArgs {
  std::string scene, generators, output, device, backend = "auto", lighting;
  std::string scene_dir;        // --scene-dir: where the scene's files resolve (confined to it)
  std::optional<Mat4> camera;   // --camera: 16 numbers, the pose as frame messages give it
  std::optional<int> spp, width, height, max_depth, light_samples;
  std::optional<uint64_t> seed;
  std::optional<Exposure> exposure;  // the scene's render.exposure when not given
  // A part of a sample-parallel render: sample indices from --samples-from, the accumulation
  // written to --accumulation (geodesic merge sums the parts).
  uint32_t samples_from = 0;
  std::string accumulation;
  std::optional<double> seconds, target_error;
  std::string report;  // --report FILE.json: the series, also as FILE.csv
  std::string dump_shaders, pipeline_cache;
  PipelineVariant variant = PipelineVariant::Specialised;
};

long parse_int(const std::string& flag, const std::string& value, long min, long max) {
  size_t used = 0;
  long v = 0;
  try {
    v = std::stol(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size() || v < min || v > max)
    throw std::invalid_argument(flag + ": must be an integer in [" + std::to_string(min) + ", " +
                                std::to_string(max) + "], not \"" + value + "\"");
  return v;
}

// "m00,m01,...,m33": the camera isometry, row-major (commas or spaces between the numbers).
Mat4 parse_camera(std::string text) {
  std::replace(text.begin(), text.end(), ',', ' ');
  std::istringstream in(text);
  Mat4 pose;
  int count = 0;
  for (double v; in >> v; ++count)
    if (count < 16) pose.m[count / 4][count % 4] = v;
  if (count != 16 || !in.eof())
    throw std::invalid_argument("--camera: must be 16 numbers (the camera isometry, row-major)");
  return pose;
}

RenderArgs parse(int argc, char** argv) {
  RenderArgs a;
  for (int i = 0; i < argc; ++i) {
    const std::string flag = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(flag + ": needs a value");
      return argv[++i];
    };
    if (flag == "-o" || flag == "--output") a.output = value();
    else if (flag == "--spp" || flag == "--samples") {
      if (a.spp) throw std::invalid_argument("--spp and --samples: give one");
      a.spp = parse_int(flag, value(), 1, 1 << 24);
    }
    else if (flag == "--samples-from") a.samples_from = uint32_t(parse_int(flag, value(), 0, 1 << 30));
    else if (flag == "--accumulation") {
      a.accumulation = value();
      if (std::filesystem::path(a.accumulation).extension() != ".exr")
        throw std::invalid_argument("--accumulation: must name a .exr file");
    }
    else if (flag == "--time") {
      const std::string v = value();
      double s = 0;
      try { s = std::stod(v); } catch (const std::exception&) { s = -1; }
      if (!(s > 0)) throw std::invalid_argument("--time: must be a number of seconds > 0");
      a.seconds = s;
    }
    else if (flag == "--target-error") {
      const std::string v = value();
      size_t used = 0;
      double e = 0;
      try { e = std::stod(v, &used); } catch (const std::exception&) { used = 0; }
      if (used != v.size() || !(e > 0 && e < 1))
        throw std::invalid_argument("--target-error: must be a relative error in (0, 1), not \"" +
                                    v + "\"");
      a.target_error = e;
    }
    else if (flag == "--report") {
      a.report = value();
      if (std::filesystem::path(a.report).extension() != ".json")
        throw std::invalid_argument("--report: must name a .json file (the CSV goes next to it)");
    }
    else if (flag == "--width") a.width = parse_int(flag, value(), 1, 8192);
    else if (flag == "--height") a.height = parse_int(flag, value(), 1, 8192);
    else if (flag == "--max-depth") a.max_depth = parse_int(flag, value(), 0, 64);
    else if (flag == "--light-samples")
      a.light_samples = parse_int(flag, value(), 1, kMaxLightSamples);
    else if (flag == "--seed") a.seed = parse_int(flag, value(), 0, 1L << 62);
    else if (flag == "--device") a.device = value();
    else if (flag == "--generators") a.generators = value();
    else if (flag == "--scene-dir") a.scene_dir = value();
    else if (flag == "--camera") a.camera = parse_camera(value());
    else if (flag == "--backend") a.backend = value();
    else if (flag == "--dump-shaders") a.dump_shaders = value();
    else if (flag == "--pipeline-cache") a.pipeline_cache = value();
    else if (flag == "--pipeline") {
      const std::string v = value();
      if (v != "specialised" && v != "all-features")
        throw std::invalid_argument("--pipeline: must be \"specialised\" or \"all-features\", not \"" +
                                    v + "\"");
      a.variant = v == "specialised" ? PipelineVariant::Specialised : PipelineVariant::AllFeatures;
    }
    else if (flag == "--exposure") {
      try {
        a.exposure = parse_exposure(value());
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("--exposure: " + std::string(e.what()));
      }
    }
    else if (flag == "--lighting") {
      a.lighting = value();
      if (a.lighting != "physical" && a.lighting != "paper")
        throw std::invalid_argument("--lighting: must be \"physical\" or \"paper\", not \"" +
                                    a.lighting + "\"");
    }
    else if (!flag.empty() && flag[0] == '-') throw std::invalid_argument("unknown option " + flag);
    else if (a.scene.empty()) a.scene = flag;
    else throw std::invalid_argument("unexpected argument \"" + flag + "\"");
  }
  if (a.scene.empty() == a.generators.empty())
    throw std::invalid_argument("give one of SCENE.json and --generators FILE.gen");
  if (a.output.empty() && a.accumulation.empty())
    throw std::invalid_argument("missing -o OUT.{png,exr,jpg} (or --accumulation OUT.exr)");
  // Exactly one stop condition; the scene's spp when none is given.
  std::vector<std::string> stops;
  if (a.spp) stops.push_back("--spp");
  if (a.seconds) stops.push_back("--time");
  if (a.target_error) stops.push_back("--target-error");
  if (stops.size() > 1)
    throw std::invalid_argument(stops[0] + " and " + stops[1] + ": give one, not both");
  return a;
}

// What a part's samples are of: parts merge only when this matches.
std::string view_identity(const std::string& source, const Scene& scene) {
  return std::filesystem::path(source).filename().string() + " seed " +
         std::to_string(scene.render.seed) + " depth " + std::to_string(scene.render.max_depth) +
         (scene.render.lighting == LightingModel::Paper ? " paper" : " physical");
}

}  // namespace

int render_command(int argc, char** argv) {
  const RenderArgs args = parse(argc, argv);
  const BackendKind backend = parse_backend(args.backend);
  if (!args.output.empty()) check_output_format(args.output);
  // A generator file gets the default scene inside its Dirichlet domain.
  const SceneSource source =
      !args.generators.empty() ? SceneSource::generator_file(args.generators)
      : args.scene_dir.empty() ? SceneSource::document_file(args.scene)
                               : SceneSource::document_file(args.scene, DocumentFiles(args.scene_dir, true));
  Scene scene = resolve_scene(source, {}).scene;
  if (args.width) scene.render.width = *args.width;
  if (args.height) scene.render.height = *args.height;
  if (args.max_depth) scene.render.max_depth = *args.max_depth;
  if (args.light_samples) scene.render.light_samples = *args.light_samples;
  if (args.seed) scene.render.seed = *args.seed;
  if (args.camera) {
    // Checked as a scene's "pose" is: an isometry of the scene's space, within round-off.
    const double error = model::relative_isometry_error(scene.geometry, *args.camera);
    if (!(error < 1e-6))
      throw std::invalid_argument("--camera: not an isometry of " + std::string(geometry_name(scene.geometry)) +
                                  " space (error " + std::to_string(error) + " > 1e-06)");
    scene.camera.pose = model::reorthonormalize(scene.geometry, *args.camera);
  }
  if (args.exposure) scene.render.exposure = *args.exposure;
  if (!args.lighting.empty()) {
    // The model's own Russian-roulette default comes with it.
    scene.render.lighting = args.lighting == "paper" ? LightingModel::Paper : LightingModel::Physical;
    scene.render.russian_roulette = scene.render.lighting == LightingModel::Physical;
  }
  StopCondition stop;
  stop.seconds = args.seconds;
  stop.target_error = args.target_error;
  if (!args.seconds && !args.target_error)
    stop.spp = uint32_t(args.spp.value_or(scene.render.spp));

  VulkanContext ctx(args.device);
  if (!args.pipeline_cache.empty()) ctx.pipeline_cache().set_directory(args.pipeline_cache);
  Renderer renderer(ctx, scene, backend, args.variant);
  if (!args.dump_shaders.empty()) dump_shaders(renderer, args.dump_shaders);
  const CachedPipeline& pipeline = renderer.backend().pipeline();
  std::printf("pipeline: %s; %zu KiB of SPIR-V, built in %.2f s\n",
              renderer.features().summary().c_str(), pipeline.spirv_bytes / 1024,
              pipeline.build_seconds);
  // A part starts at sample index --samples-from, on empty sums; its own count is what the stop
  // conditions see.
  const uint32_t first = args.samples_from;
  if (first > 0) renderer.restore(first, std::vector<float>(renderer.accumulation().size(), 0.0f));
  ProgressBar bar;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

  // Passes grow until one takes about a quarter second (render/service/pass_slicer.h: few submissions,
  // live progress, and a dense series early on); the stop conditions cap them. One point of the
  // series after every pass.
  ConvergenceLog log;
  PassSlicer slicer(kCliSliceSeconds, kCliMaxBatch);
  ErrorSample now;
  const char* stopped_by = nullptr;
  while (!(stopped_by = stop.met(now))) {
    if (stop.spp) slicer.limit_batch(*stop.spp - (renderer.samples() - first));
    // Error falls as 1/sqrt(spp): do not overshoot the samples the target needs by much.
    if (stop.target_error && now.error > 0 && now.spp >= 8) {
      const double needed = now.spp * std::pow(now.error / *stop.target_error, 2) - now.spp;
      slicer.limit_batch(uint32_t(std::clamp(std::ceil(needed), 1.0, double(kCliMaxBatch))));
    }
    while (!slicer.render_slice(renderer)) {}
    now = {elapsed(), renderer.samples() - first, renderer.estimated_error()};
    log.record(now);
    const std::string error =
        now.error >= 0 ? ", error " + std::to_string(now.error).substr(0, 6) : "";
    bar.update(stop.progress(now), std::to_string(now.spp) + " spp, " +
                                       std::to_string(now.seconds).substr(0, 5) + " s" + error);
  }
  const double seconds = elapsed();
  bar.finish();
  const uint32_t rendered = renderer.samples() - first;
  if (!args.output.empty()) {
    const Image image = renderer.image();
    const double stops = exposure_stops(scene.render.exposure, image);
    write_image(args.output, image, exposure_scale(stops));
    if (stops != 0)
      std::printf("%s: exposure %+.2f stops%s\n", args.output.c_str(), stops,
                  scene.render.exposure.automatic ? " (auto)" : "");
  }
  if (!args.accumulation.empty()) {
    const auto sums = renderer.accumulation();
    write_accumulation(args.accumulation,
                       {renderer.width(), renderer.height(), first, rendered,
                        view_identity(args.scene.empty() ? args.generators : args.scene, scene),
                        std::vector<float>(sums.begin(), sums.end())});
    std::printf("%s: samples [%u, %u)\n", args.accumulation.c_str(), first, first + rendered);
  }

  const double paths = double(rendered) * scene.render.width * scene.render.height;
  std::printf("%s: %u spp at %dx%d, depth %d, in %.2f s: %.3f M paths/s (%s on %s)\n",
              (args.output.empty() ? args.accumulation : args.output).c_str(), rendered, scene.render.width, scene.render.height,
              scene.render.max_depth, seconds, paths / seconds / 1e6, renderer.backend_name(),
              ctx.description().name.c_str());
  const uint64_t non_finite = renderer.non_finite_samples();
  const uint64_t truncated = renderer.trace_counters().truncated_rays;
  std::printf("%llu non-finite samples, %llu geodesics cut off at %d crossings\n",
              static_cast<unsigned long long>(non_finite), static_cast<unsigned long long>(truncated),
              scene.manifold.max_crossings);
  if (!args.report.empty()) {
    RenderReport report{args.scene.empty() ? args.generators : args.scene,
                        geometry_name(scene.geometry), ctx.description().name,
                        renderer.backend_name(), scene.render.width, scene.render.height,
                        rendered, seconds, now.error, stop, stopped_by, log, non_finite, truncated};
    write_render_report(args.report, report);
  }
  return 0;
}

}  // namespace geodesic
