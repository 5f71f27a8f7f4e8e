// `geodesic` command line: render a scene to an image, list Vulkan devices, or serve.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

namespace geodesic {
int render_command(int argc, char** argv);
int devices_command(int argc, char** argv);
int serve_command(int argc, char** argv);
int catalogue_command(int argc, char** argv);
int merge_command(int argc, char** argv);
}  // namespace geodesic

namespace {

const char* kUsage =
    "usage: geodesic <command> [options]\n"
    "commands:\n"
    "  render SCENE.json -o OUT.{png,exr,jpg} [--spp N | --time SECONDS | --target-error E]\n"
    "         [--report FILE.json] [--width W] [--height H] [--max-depth D] [--seed S]\n"
    "         [--light-samples N]\n"
    "         [--device NAME|INDEX] [--lighting physical|paper] [--exposure STOPS|auto]\n"
    "         [--backend auto|ray-query|pipeline] [--dump-shaders DIR]\n"
    "         [--pipeline specialised|all-features] [--pipeline-cache DIR]\n"
    "         [--samples-from K --samples N --accumulation PART.exr]  a part of a\n"
    "                sample-parallel render: sample indices [K, K+N), the un-normalised sums\n"
    "  merge PART.exr... -o OUT.{png,exr,jpg} [--accumulation ALL.exr] [--report FILE.json]\n"
    "        [--exposure STOPS|auto]  (PNG and JPEG: values times 2^STOPS; EXR: radiance)\n"
    "                sum the parts' accumulations into one image (one render of all samples)\n"
    "  render --generators FILE.gen -o OUT ...  the same options, rendering a default scene\n"
    "                inside the space of a generator file (Curved Spaces .gen or SnapPy)\n"
    "  catalogue [ROOT]  write the manifold catalogue (ROOT/catalogue/*.gen, README.md and\n"
    "                ROOT/scenes/catalogue/*.json) from its closed forms; ROOT defaults to .\n"
    "  devices       list Vulkan devices and whether each can ray-trace\n"
    "  serve [--host H] [--port P] [--device NAME|INDEX] [--web DIR] [--data DIR]\n"
    "        [--token T] [--max-jobs N] [--max-queue N] [--checkpoint-seconds S]\n"
    "        [--max-sessions N] [--max-depth N] [--keep-jobs N] [--jobs-backend local|slurm]\n"
    "        [--slurm-parts N] [--slurm-scripts DIR]\n"
    "                the render daemon: HTTP and WebSocket (docs/protocol.md), default\n"
    "                127.0.0.1:8080, until SIGINT or SIGTERM; --jobs-backend slurm hands\n"
    "                REST jobs to a Slurm cluster (deploy/slurm) split into N parts\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string command = argv[1];
  for (int i = 2; i < argc; ++i)
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
      std::fputs(kUsage, stdout);
      return 0;
    }
  try {
    if (command == "render") return geodesic::render_command(argc - 2, argv + 2);
    if (command == "devices") return geodesic::devices_command(argc - 2, argv + 2);
    if (command == "serve") return geodesic::serve_command(argc - 2, argv + 2);
    if (command == "merge") return geodesic::merge_command(argc - 2, argv + 2);
    if (command == "catalogue") return geodesic::catalogue_command(argc - 2, argv + 2);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "geodesic %s: %s\n", command.c_str(), e.what());
    return 1;
  }
  std::fprintf(stderr, "geodesic: unknown command \"%s\"\n%s", command.c_str(), kUsage);
  return 2;
}
