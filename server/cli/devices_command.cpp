#include <cstdio>

#include "render/device/trace_backend.h"
#include "render/device/vulkan_context.h"

namespace geodesic {

int devices_command(int, char**) {
  const auto devices = VulkanContext::list_devices();
  if (devices.empty()) std::printf("no Vulkan devices\n");
  for (const auto& d : devices) {
    std::printf("[%u] %s (%s, %s)\n", d.index, d.name.c_str(), d.type.c_str(), d.driver.c_str());
    if (d.can_ray_trace()) {
      std::printf("    can ray-trace: ray-tracing pipeline %s, ray query %s; default back end %s\n",
                  d.ray_tracing_pipeline ? "yes" : "no", d.ray_query ? "yes" : "no",
                  resolve_backend(BackendKind::Auto, d) == BackendKind::RayQuery ? "ray-query"
                                                                                 : "pipeline");
    } else {
      std::printf("    cannot ray-trace: missing");
      for (const auto& m : d.missing) std::printf(" %s", m.c_str());
      std::printf("\n");
    }
  }
  return 0;
}

}  // namespace geodesic
