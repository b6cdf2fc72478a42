// Which device a Context runs on: what ray tracing needs of a device, the caller's preference
// (and PROCEDURAY_DEVICE), and a report of every device when none fits.
//
//   const auto missing = proceduray::vk::missing_for_ray_tracing(physical);   // {} when it can ray trace
//   VkPhysicalDevice device = proceduray::vk::select_device(instance, proceduray::vk::DevicePreference::cpu);
//
// Choice: an NVIDIA (or other discrete) GPU when one offers ray tracing, else any other device that
// does (Mesa's lavapipe on a machine without a GPU). The environment variable
// PROCEDURAY_DEVICE=cpu|gpu|auto overrides DevicePreference::automatic. When nothing fits,
// select_device throws NoRayTracingDevice saying what each device lacks and how to get one that can.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/vk/error.hpp>
#include <proceduray/vk/structs.hpp>

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace proceduray::vk {

/// Which kind of device to run on.
enum class DevicePreference {
  automatic,  ///< a GPU when one offers ray tracing, else a CPU device (lavapipe); PROCEDURAY_DEVICE may override
  gpu,        ///< a GPU only; throws when none offers ray tracing
  cpu,        ///< a CPU device (lavapipe) only
};

/// Thrown when no device can ray trace: says what each device lacks and how to get one that can.
class NoRayTracingDevice : public EnvironmentError {
 public:
  using EnvironmentError::EnvironmentError;
};

namespace detail {

inline constexpr const char* required_device_extensions[] = {
    VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
    VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
    VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME,
};

/// The preference with PROCEDURAY_DEVICE applied to `automatic`; throws UsageError for an unknown value.
PROCEDURAY_DECL DevicePreference preference_from_environment(DevicePreference preference);

PROCEDURAY_DECL const char* to_string(DevicePreference p);

/// Lower is preferred: discrete GPU, integrated, virtual, other, then CPU.
PROCEDURAY_DECL int rank(VkPhysicalDeviceType type);

}  // namespace detail

/// What a physical device lacks for ray tracing, as readable phrases; empty when it has everything.
PROCEDURAY_DECL std::vector<std::string> missing_for_ray_tracing(VkPhysicalDevice device);

/// The best device of `instance` that can ray trace and fits `preference` (automatic honours
/// PROCEDURAY_DEVICE); throws NoRayTracingDevice listing every device and what it lacks.
PROCEDURAY_DECL VkPhysicalDevice select_device(VkInstance instance, DevicePreference preference);

}  // namespace proceduray::vk

#include "proceduray/vk/device_selection-inl.hpp"  // the bodies (config.hpp)
