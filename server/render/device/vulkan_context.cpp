#include "render/device/vulkan_context.h"

#include "render/device/pipeline_cache.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <mutex>
#include <set>

#include "render/device/fault_injection.h"

namespace geodesic {
namespace {

const char* const kRequiredExtensions[] = {
    VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
    VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME,
};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

const char* type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual-gpu";
    default: return "other";
  }
}

VkInstance create_instance() {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "geodesic";
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  VkInstance instance = VK_NULL_HANDLE;
  VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw VulkanError(
        "no Vulkan driver found: install a driver with ray tracing (Mesa lavapipe >= 24.1, "
        "Debian package mesa-vulkan-drivers from bookworm-backports, or a GPU driver)");
  vk_check(result, "vkCreateInstance");
  return instance;
}

std::vector<VkPhysicalDevice> physical_devices(VkInstance instance) {
  uint32_t count = 0;
  vk_check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  vk_check(vkEnumeratePhysicalDevices(instance, &count, devices.data()),
           "vkEnumeratePhysicalDevices");
  return devices;
}

DeviceDescription describe(VkPhysicalDevice device, uint32_t index) {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
  vkGetPhysicalDeviceProperties2(device, &props);

  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  std::set<std::string> names;
  for (const auto& e : extensions) names.insert(e.extensionName);

  DeviceDescription d;
  d.index = index;
  d.name = props.properties.deviceName;
  d.type = type_name(props.properties.deviceType);
  d.driver = std::string(driver.driverName) + " " + driver.driverInfo;
  d.cpu = props.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  if (props.properties.apiVersion < VK_API_VERSION_1_2) d.missing.push_back("Vulkan 1.2");
  for (const char* ext : kRequiredExtensions)
    if (!names.count(ext)) d.missing.push_back(ext);
  d.acceleration_structure = names.count(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) > 0;
  d.ray_tracing_pipeline = names.count(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME) > 0;
  d.ray_query = names.count(VK_KHR_RAY_QUERY_EXTENSION_NAME) > 0;
  if (!d.ray_tracing_pipeline && !d.ray_query)
    d.missing.push_back(std::string(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME) + " or " +
                        VK_KHR_RAY_QUERY_EXTENSION_NAME);
  return d;
}

std::string no_device_message(const std::vector<DeviceDescription>& devices,
                              const std::string& selector) {
  std::string msg = selector.empty() ? "no Vulkan device can ray-trace"
                                     : "no Vulkan device matches --device \"" + selector + "\"";
  if (devices.empty()) msg += " (no Vulkan devices found)";
  for (const auto& d : devices) {
    msg += "\n  [" + std::to_string(d.index) + "] " + d.name + ": ";
    if (d.can_ray_trace()) {
      msg += "can ray-trace";
    } else {
      msg += "missing";
      for (const auto& m : d.missing) msg += " " + m;
    }
  }
  const bool any = std::any_of(devices.begin(), devices.end(),
                               [](const DeviceDescription& d) { return d.can_ray_trace(); });
  if (!any)
    msg += "\nlavapipe gained ray tracing in Mesa 24.1: on Debian 12 install "
           "mesa-vulkan-drivers from bookworm-backports (scripts/install-deps.sh does this)";
  return msg;
}

// Picks the device to use: by index or name, else the first GPU that can ray-trace, else
// the first CPU device (lavapipe) that can.
std::optional<size_t> choose(const std::vector<DeviceDescription>& devices,
                             const std::string& selector) {
  if (!selector.empty()) {
    bool numeric = std::all_of(selector.begin(), selector.end(), ::isdigit);
    for (size_t i = 0; i < devices.size(); ++i) {
      bool match = numeric ? std::to_string(i) == selector
                           : lower(devices[i].name).find(lower(selector)) != std::string::npos ||
                                 (lower(selector) == "lavapipe" && devices[i].cpu);
      if (match && devices[i].can_ray_trace()) return i;
    }
    return std::nullopt;
  }
  for (size_t i = 0; i < devices.size(); ++i)
    if (!devices[i].cpu && devices[i].can_ray_trace()) return i;
  for (size_t i = 0; i < devices.size(); ++i)
    if (devices[i].can_ray_trace()) return i;
  return std::nullopt;
}

}  // namespace

std::vector<DeviceDescription> VulkanContext::list_devices() {
  VkInstance instance = create_instance();
  std::vector<DeviceDescription> out;
  auto devices = physical_devices(instance);
  for (uint32_t i = 0; i < devices.size(); ++i) out.push_back(describe(devices[i], i));
  vkDestroyInstance(instance, nullptr);
  return out;
}

VulkanContext::VulkanContext(const std::string& selector) {
  instance_ = create_instance();
  auto devices = physical_devices(instance_);
  std::vector<DeviceDescription> descriptions;
  for (uint32_t i = 0; i < devices.size(); ++i) descriptions.push_back(describe(devices[i], i));
  auto chosen = choose(descriptions, selector);
  if (!chosen) {
    vkDestroyInstance(instance_, nullptr);
    throw VulkanError(no_device_message(descriptions, selector));
  }
  physical_device_ = devices[*chosen];
  description_ = descriptions[*chosen];

  uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, families.data());
  queue_family_ = UINT32_MAX;
  for (uint32_t i = 0; i < family_count; ++i)
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) { queue_family_ = i; break; }
  if (queue_family_ == UINT32_MAX) throw VulkanError(description_.name + ": no compute queue");

  // Feature chain: buffer device addresses, acceleration structures, and whichever of the
  // two tracing paths the device offers.
  VkPhysicalDeviceRayQueryFeaturesKHR ray_query{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipeline{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR accel{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  std::vector<const char*> extensions(std::begin(kRequiredExtensions),
                                      std::end(kRequiredExtensions));
  void* chain = &accel;
  accel.pNext = &v12;
  if (description_.ray_query) {
    ray_query.pNext = chain;
    chain = &ray_query;
    extensions.push_back(VK_KHR_RAY_QUERY_EXTENSION_NAME);
  }
  if (description_.ray_tracing_pipeline) {
    pipeline.pNext = chain;
    chain = &pipeline;
    extensions.push_back(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
  }
  features.pNext = chain;
  vkGetPhysicalDeviceFeatures2(physical_device_, &features);
  if (!v12.bufferDeviceAddress || !accel.accelerationStructure)
    throw VulkanError(description_.name + ": lacks bufferDeviceAddress/accelerationStructure");
  description_.ray_query = description_.ray_query && ray_query.rayQuery;
  description_.float64 = features.features.shaderFloat64;
  description_.ray_tracing_pipeline =
      description_.ray_tracing_pipeline && pipeline.rayTracingPipeline;
  description_.primitive_culling =
      description_.ray_tracing_pipeline && pipeline.rayTraversalPrimitiveCulling;

  // Enable only what is needed, keeping the queried chain.
  VkPhysicalDeviceFeatures2 enabled = features;
  enabled.features = VkPhysicalDeviceFeatures{};
  enabled.features.shaderInt64 = features.features.shaderInt64;
  enabled.features.shaderFloat64 = features.features.shaderFloat64;  // bench/float64_cost

  float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &enabled};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  vk_check(vkCreateDevice(physical_device_, &info, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

  auto load = [&](auto& fn, const char* name) {
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(vkGetDeviceProcAddr(device_, name));
  };
  load(rt_.get_build_sizes, "vkGetAccelerationStructureBuildSizesKHR");
  load(rt_.create_acceleration_structure, "vkCreateAccelerationStructureKHR");
  load(rt_.destroy_acceleration_structure, "vkDestroyAccelerationStructureKHR");
  load(rt_.cmd_build_acceleration_structures, "vkCmdBuildAccelerationStructuresKHR");
  load(rt_.get_acceleration_structure_address, "vkGetAccelerationStructureDeviceAddressKHR");
  if (description_.ray_tracing_pipeline) {
    load(rt_.create_ray_tracing_pipelines, "vkCreateRayTracingPipelinesKHR");
    load(rt_.get_shader_group_handles, "vkGetRayTracingShaderGroupHandlesKHR");
    load(rt_.cmd_trace_rays, "vkCmdTraceRaysKHR");
  }

  vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);
  pipeline_properties_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR;
  acceleration_properties_.sType =
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR;
  pipeline_properties_.pNext = &acceleration_properties_;
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                    &pipeline_properties_};
  vkGetPhysicalDeviceProperties2(physical_device_, &props);
  pipeline_cache_ = std::make_unique<PipelineCache>(device_, props.properties.pipelineCacheUUID);
}

VulkanContext::~VulkanContext() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    pipeline_cache_.reset();
    vkDestroyDevice(device_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

uint32_t VulkanContext::find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags wanted) const {
  for (uint32_t i = 0; i < memory_properties_.memoryTypeCount; ++i)
    if ((type_bits & (1u << i)) &&
        (memory_properties_.memoryTypes[i].propertyFlags & wanted) == wanted)
      return i;
  throw VulkanError("no memory type with the wanted properties");
}

VulkanContext::OneShot::OneShot(VkDevice device, uint32_t queue_family) : device(device) {
  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pool_info.queueFamilyIndex = queue_family;
  vk_check(vkCreateCommandPool(device, &pool_info, nullptr, &pool), "vkCreateCommandPool");
  try {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    vk_check(vkAllocateCommandBuffers(device, &alloc, &cmd), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    vk_check(vkCreateFence(device, &fence_info, nullptr, &fence), "vkCreateFence");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk_check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  } catch (...) {
    release();
    throw;
  }
}

VulkanContext::OneShot::~OneShot() { release(); }

// Destroying the pool frees its command buffer; null handles are ignored.
void VulkanContext::OneShot::release() {
  vkDestroyFence(device, fence, nullptr);
  vkDestroyCommandPool(device, pool, nullptr);
}

void VulkanContext::submit(OneShot& shot) {
  // A lost device stays lost: the driver answers every later submission so.
  auto checked = [this](VkResult result, const char* what) {
    if (result == VK_ERROR_DEVICE_LOST) lost_ = true;
    vk_check(result, what);
  };
  if (lost_) checked(VK_ERROR_DEVICE_LOST, "vkQueueSubmit");
  checked(vkEndCommandBuffer(shot.cmd), "vkEndCommandBuffer");
  VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  info.commandBufferCount = 1;
  info.pCommandBuffers = &shot.cmd;
  VkResult submitted = fault::next_submission();  // VK_SUCCESS unless a test injects a fault
  if (submitted == VK_SUCCESS) {
    std::lock_guard hold(queue_mutex_);
    submitted = vkQueueSubmit(queue_, 1, &info, shot.fence);
  }
  checked(submitted, "vkQueueSubmit");
  checked(vkWaitForFences(device_, 1, &shot.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

}  // namespace geodesic
