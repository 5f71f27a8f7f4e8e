#include "render/device/fault_injection.h"

#include <atomic>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace geodesic::fault {
namespace {

struct Fault {
  VkResult result = VK_SUCCESS;
  uint64_t at = 0;  // submission number; 0: none
};

Fault parse(const char* text) {
  if (!text || !*text) return {};
  const std::string spec = text;
  const size_t at = spec.find('@');
  const std::string kind = spec.substr(0, at);
  Fault fault;
  if (kind == "device-lost") fault.result = VK_ERROR_DEVICE_LOST;
  else if (kind == "oom") fault.result = VK_ERROR_OUT_OF_DEVICE_MEMORY;
  size_t used = 0;
  try {
    if (at != std::string::npos) fault.at = std::stoull(spec.substr(at + 1), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (fault.result == VK_SUCCESS || used == 0 || used != spec.size() - at - 1 || fault.at == 0)
    throw std::invalid_argument("GEODESIC_FAULT: expected device-lost@N or oom@N (N >= 1), not \"" +
                                spec + "\"");
  return fault;
}

}  // namespace

VkResult next_submission() {
  static const Fault fault = parse(std::getenv("GEODESIC_FAULT"));
  static std::atomic<uint64_t> submissions{0};
  if (fault.at == 0) return VK_SUCCESS;
  return ++submissions == fault.at ? fault.result : VK_SUCCESS;
}

}  // namespace geodesic::fault
