// The bodies of proceduray/vk/device_selection.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/device_selection.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk::detail {

PROCEDURAY_DECL DevicePreference preference_from_environment(DevicePreference preference) {
  if (preference != DevicePreference::automatic) return preference;
  const char* env = std::getenv("PROCEDURAY_DEVICE");
  if (env == nullptr || *env == '\0' || std::strcmp(env, "auto") == 0) return preference;
  if (std::strcmp(env, "cpu") == 0) return DevicePreference::cpu;
  if (std::strcmp(env, "gpu") == 0) return DevicePreference::gpu;
  throw UsageError(std::string("Context: PROCEDURAY_DEVICE='") + env +
                   "' is not a device choice; use cpu, gpu or auto");
}

PROCEDURAY_DECL const char* to_string(DevicePreference p) {
  return p == DevicePreference::cpu ? "cpu" : p == DevicePreference::gpu ? "gpu" : "auto";
}

PROCEDURAY_DECL int rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 4;
    default: return 3;
  }
}

}  // namespace proceduray::vk::detail

namespace proceduray::vk {

PROCEDURAY_DECL std::vector<std::string> missing_for_ray_tracing(VkPhysicalDevice device) {
  std::vector<std::string> missing;
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(device, &props);
  if (props.apiVersion < VK_API_VERSION_1_2) missing.emplace_back("Vulkan 1.2");
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  for (const char* name : detail::required_device_extensions) {
    bool found = std::any_of(extensions.begin(), extensions.end(),
                             [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
    if (!found) missing.emplace_back(name);
  }
  if (!missing.empty()) return missing;
  auto as = make<VkPhysicalDeviceAccelerationStructureFeaturesKHR>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR);
  auto rt = make<VkPhysicalDeviceRayTracingPipelineFeaturesKHR>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR, &as);
  auto v12 = make<VkPhysicalDeviceVulkan12Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &rt);
  auto features = make<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v12);
  vkGetPhysicalDeviceFeatures2(device, &features);
  if (!rt.rayTracingPipeline) missing.emplace_back("feature rayTracingPipeline");
  if (!as.accelerationStructure) missing.emplace_back("feature accelerationStructure");
  if (!v12.bufferDeviceAddress) missing.emplace_back("feature bufferDeviceAddress");
  if (!v12.scalarBlockLayout) missing.emplace_back("feature scalarBlockLayout");
  return missing;
}

PROCEDURAY_DECL VkPhysicalDevice select_device(VkInstance instance, DevicePreference preference) {
  preference = detail::preference_from_environment(preference);
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
  VkPhysicalDevice best = VK_NULL_HANDLE;
  int best_rank = 1 << 30;
  std::string report;
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(device, &props);
    const bool cpu = props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const auto missing = missing_for_ray_tracing(device);
    report += std::string("\n  ") + props.deviceName + (cpu ? " (cpu)" : " (gpu)") + ": ";
    if (!missing.empty()) {
      report += "lacks";
      for (const auto& m : missing) report += " " + m;
      continue;
    }
    if ((preference == DevicePreference::cpu && !cpu) || (preference == DevicePreference::gpu && cpu)) {
      report += std::string("can ray trace but is not a ") + detail::to_string(preference) + " device";
      continue;
    }
    report += "can ray trace";
    if (detail::rank(props.deviceType) < best_rank) {
      best_rank = detail::rank(props.deviceType);
      best = device;
    }
  }
  if (best != VK_NULL_HANDLE) return best;
  throw NoRayTracingDevice(
      std::string("Context: no Vulkan device can ray trace (asked for device '") + detail::to_string(preference) +
      "'). Devices found:" + (devices.empty() ? std::string("\n  none") : report) +
      "\nRay tracing needs VK_KHR_ray_tracing_pipeline and VK_KHR_acceleration_structure. Without a GPU install "
      "Mesa >= 24.1 for lavapipe (Debian 12: tools/setup.sh, or apt-get install -t bookworm-backports "
      "mesa-vulkan-drivers); with an NVIDIA GPU install its driver; or set PROCEDURAY_DEVICE=auto");
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
