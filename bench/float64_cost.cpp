// What double precision costs on the device: the sphere-intersection arithmetic of
// bench/float64_cost.comp, compiled for float and for double, run over the same 10^6 cases
// (64 intersections each); prints the best of five timed runs and the ratio (docs/numerics.md).
//   float64_cost [--device NAME|INDEX] [--invocations N] [--repeats R]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "render/device/gpu_buffer.h"
#include "render/device/storage_kernel.h"
#include "render/device/vulkan_context.h"

namespace {

using namespace geodesic;

std::vector<uint32_t> read_spirv(const std::string& path) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) throw std::runtime_error("cannot read " + path);
  std::vector<uint32_t> code(static_cast<size_t>(file.tellg()) / 4);
  file.seekg(0);
  file.read(reinterpret_cast<char*>(code.data()), code.size() * 4);
  return code;
}

struct Push {
  uint32_t count;
  uint32_t repeats;
};

// Seconds for one dispatch of `kernel` over every invocation, and the sum of its outputs.
std::pair<double, double> run(VulkanContext& ctx, const StorageKernel& kernel,
                              const GpuBuffer& output, Push push) {
  const auto start = std::chrono::steady_clock::now();
  ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) { kernel.record(cmd, &push, (push.count + 63) / 64); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto* values = static_cast<const float*>(output.mapped());
  double sum = 0;
  for (uint32_t i = 0; i < push.count; ++i) sum += values[i];
  return {seconds, sum};
}

}  // namespace

int main(int argc, char** argv) {
  std::string device = "";
  uint32_t invocations = 1u << 20, repeats = 64;  // 10^6 cases, each intersected 64 times
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--device" && i + 1 < argc) device = argv[++i];
    else if (a == "--invocations" && i + 1 < argc) invocations = std::stoul(argv[++i]);
    else if (a == "--repeats" && i + 1 < argc) repeats = std::stoul(argv[++i]);
  }
  try {
    // The renderer's device, which enables shaderFloat64 where the device has it.
    VulkanContext ctx(device);
    if (!ctx.description().float64)
      throw std::runtime_error(ctx.description().name + " has no shaderFloat64");
    GpuBuffer output(ctx, invocations * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    const double intersections = double(invocations) * repeats;
    std::printf("%s: %.3g sphere intersections per dispatch, best of 5\n", ctx.description().name.c_str(),
                intersections);
    double best[2] = {1e300, 1e300};
    const char* precisions[2] = {"float", "double"};
    for (int p = 0; p < 2; ++p) {
      StorageKernel kernel(ctx, read_spirv(std::string(FLOAT64_COST_SPV_DIR) + "/float64_cost." +
                                           precisions[p] + ".spv"),
                           1, sizeof(Push));
      kernel.bind({&output});
      const Push push{invocations, repeats};
      run(ctx, kernel, output, push);  // warm-up
      double sum = 0;
      for (int r = 0; r < 5; ++r) {
        const auto [seconds, s] = run(ctx, kernel, output, push);
        best[p] = std::min(best[p], seconds);
        sum = s;
      }
      std::printf("  %-6s %8.2f ms  %8.1f M intersections/s  (checksum %.9g)\n", precisions[p],
                  best[p] * 1e3, intersections / best[p] * 1e-6, sum);
    }
    std::printf("  double / float time: %.2fx\n", best[1] / best[0]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "float64_cost: %s\n", e.what());
    return 1;
  }
}
