// Runs a test probe: a compute shader reading an array of cases from binding 0 and writing one
// result per case to binding 1, with the case count as its only push constant. Probes are
// compiled at run time for one model geometry, like every entry point.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "render/device/gpu_buffer.h"
#include "render/device/storage_kernel.h"
#include "render/device/vulkan_context.h"
#include "render/prepare/pipeline_features.h"
#include "render/prepare/shader_compiler.h"

namespace geodesic::test {

class ProbeRunner {
 public:
  static constexpr uint32_t kGroupSize = 64;  // local_size_x of every probe shader

  ProbeRunner(VulkanContext& ctx, const std::string& shader, GeometryKind geometry)
      : ctx_(ctx),
        kernel_(ctx, compile_shader(shader, {geometry_define(geometry)}).spirv, 2,
                sizeof(uint32_t)) {}

  // One result per case. Case and Result must match the shader's std430 structs.
  template <typename Result, typename Case>
  std::vector<Result> run(const std::vector<Case>& cases) {
    const auto count = static_cast<uint32_t>(cases.size());
    GpuBuffer input = GpuBuffer::from_vector(ctx_, cases, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    GpuBuffer output(ctx_, std::max<VkDeviceSize>(1, count) * sizeof(Result),
                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    kernel_.bind({&input, &output});
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
      kernel_.record(cmd, &count, (count + kGroupSize - 1) / kGroupSize);
    });
    std::vector<Result> results(count);
    std::memcpy(results.data(), output.mapped(), count * sizeof(Result));
    return results;
  }

 private:
  VulkanContext& ctx_;
  StorageKernel kernel_;
};

}  // namespace geodesic::test
