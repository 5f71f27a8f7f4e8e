#include <chrono>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "cli/progress_bar.h"
#include "render/image_io.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace geodesic {
namespace {

struct RenderArgs {
  std::string scene, output, device, backend = "auto";
  std::optional<int> spp, width, height, max_depth;
  std::optional<uint64_t> seed;
  std::optional<double> seconds;
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

RenderArgs parse(int argc, char** argv) {
  RenderArgs a;
  for (int i = 0; i < argc; ++i) {
    const std::string flag = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(flag + ": needs a value");
      return argv[++i];
    };
    if (flag == "-o" || flag == "--output") a.output = value();
    else if (flag == "--spp") a.spp = parse_int(flag, value(), 1, 1 << 24);
    else if (flag == "--time") {
      const std::string v = value();
      double s = 0;
      try { s = std::stod(v); } catch (const std::exception&) { s = -1; }
      if (!(s > 0)) throw std::invalid_argument("--time: must be a number of seconds > 0");
      a.seconds = s;
    }
    else if (flag == "--width") a.width = parse_int(flag, value(), 1, 8192);
    else if (flag == "--height") a.height = parse_int(flag, value(), 1, 8192);
    else if (flag == "--max-depth") a.max_depth = parse_int(flag, value(), 0, 64);
    else if (flag == "--seed") a.seed = parse_int(flag, value(), 0, 1L << 62);
    else if (flag == "--device") a.device = value();
    else if (flag == "--backend") a.backend = value();
    else if (!flag.empty() && flag[0] == '-') throw std::invalid_argument("unknown option " + flag);
    else if (a.scene.empty()) a.scene = flag;
    else throw std::invalid_argument("unexpected argument \"" + flag + "\"");
  }
  if (a.scene.empty()) throw std::invalid_argument("missing SCENE.json");
  if (a.output.empty()) throw std::invalid_argument("missing -o OUT.{png,exr,jpg}");
  if (a.spp && a.seconds) throw std::invalid_argument("--spp and --time: give one, not both");
  return a;
}

}  // namespace

int render_command(int argc, char** argv) {
  const RenderArgs args = parse(argc, argv);
  const BackendKind backend = parse_backend(args.backend);
  check_output_format(args.output);
  Scene scene = load_scene_file(args.scene);
  if (args.width) scene.render.width = *args.width;
  if (args.height) scene.render.height = *args.height;
  if (args.max_depth) scene.render.max_depth = *args.max_depth;
  if (args.seed) scene.render.seed = *args.seed;
  const uint32_t target_spp = static_cast<uint32_t>(args.spp.value_or(scene.render.spp));

  VulkanContext ctx(args.device);
  Renderer renderer(ctx, scene, backend);
  ProgressBar bar;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

  // Batches grow until one takes about a quarter second: few submissions, live progress.
  uint32_t batch = 1;
  while (args.seconds ? elapsed() < *args.seconds : renderer.samples() < target_spp) {
    if (!args.seconds) batch = std::min(batch, target_spp - renderer.samples());
    const double before = elapsed();
    renderer.add_samples(batch);
    const double took = elapsed() - before;
    if (took < 0.25 && batch < 64) batch *= 2;
    const double fraction = args.seconds ? elapsed() / *args.seconds
                                         : double(renderer.samples()) / target_spp;
    bar.update(fraction, std::to_string(renderer.samples()) + " spp, " +
                             std::to_string(elapsed()).substr(0, 5) + " s");
  }
  const double seconds = elapsed();
  bar.finish();
  write_image(args.output, renderer.image());

  const double paths = double(renderer.samples()) * scene.render.width * scene.render.height;
  std::printf("%s: %u spp at %dx%d, depth %d, in %.2f s: %.3f M paths/s (%s on %s)\n",
              args.output.c_str(), renderer.samples(), scene.render.width, scene.render.height,
              scene.render.max_depth, seconds, paths / seconds / 1e6, renderer.backend_name(),
              ctx.description().name.c_str());
  return 0;
}

}  // namespace geodesic
