// Fault injection for tests: device loss and device memory exhaustion cannot be provoked on
// lavapipe, so GEODESIC_FAULT=device-lost@N or oom@N makes the Nth queue submission of the
// process (counted from 1) fail with VK_ERROR_DEVICE_LOST or VK_ERROR_OUT_OF_DEVICE_MEMORY,
// as a driver would report it. Read once; unset or empty injects nothing.
#pragma once

#include <vulkan/vulkan.h>

namespace geodesic::fault {

// Counts one queue submission; the result the driver should be taken to have returned for it
// (VK_SUCCESS: submit for real). Throws std::invalid_argument for a malformed GEODESIC_FAULT.
VkResult next_submission();

}  // namespace geodesic::fault
