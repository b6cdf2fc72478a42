// The bodies of proceduray/vk/error.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/error.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL std::string result_name(VkResult r) {
  switch (r) {
#define PROCEDURAY_RESULT_CASE(x) \
  case x:                         \
    return #x;
    PROCEDURAY_RESULT_CASE(VK_SUCCESS)
    PROCEDURAY_RESULT_CASE(VK_NOT_READY)
    PROCEDURAY_RESULT_CASE(VK_TIMEOUT)
    PROCEDURAY_RESULT_CASE(VK_INCOMPLETE)
    PROCEDURAY_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    PROCEDURAY_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    PROCEDURAY_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
    PROCEDURAY_RESULT_CASE(VK_ERROR_DEVICE_LOST)
    PROCEDURAY_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    PROCEDURAY_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    PROCEDURAY_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    PROCEDURAY_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    PROCEDURAY_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    PROCEDURAY_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    PROCEDURAY_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    PROCEDURAY_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
    PROCEDURAY_RESULT_CASE(VK_ERROR_UNKNOWN)
    PROCEDURAY_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    PROCEDURAY_RESULT_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    PROCEDURAY_RESULT_CASE(VK_ERROR_FRAGMENTATION)
    PROCEDURAY_RESULT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    PROCEDURAY_RESULT_CASE(VK_PIPELINE_COMPILE_REQUIRED)
    PROCEDURAY_RESULT_CASE(VK_THREAD_IDLE_KHR)
    PROCEDURAY_RESULT_CASE(VK_THREAD_DONE_KHR)
    PROCEDURAY_RESULT_CASE(VK_OPERATION_DEFERRED_KHR)
    PROCEDURAY_RESULT_CASE(VK_OPERATION_NOT_DEFERRED_KHR)
#undef PROCEDURAY_RESULT_CASE
    default:
      return "VkResult(" + std::to_string(static_cast<int>(r)) + ")";
  }
}

PROCEDURAY_DECL const std::error_category& vulkan_category() noexcept {
  struct Category final : std::error_category {
    const char* name() const noexcept override { return "vulkan"; }
    std::string message(int code) const override { return result_name(static_cast<VkResult>(code)); }
  };
  static const Category category;
  return category;
}

PROCEDURAY_DECL void check(VkResult result, const char* call, std::string_view context) {
  if (result == VK_SUCCESS) return;  // a string_view: the frame loop's checks build no string
  std::string what = std::string(call) + " failed";
  if (!context.empty()) what += " (" + std::string(context) + ")";
  if (result == VK_ERROR_DEVICE_LOST) {
    what += ": the device was lost; a shader ran too long or read out of bounds. Run with the validation "
            "layer (ContextOptions::validation) to find the cause";
  } else if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY) {
    what += ": out of memory; render smaller images or fewer instances";
  }
  throw VulkanError(result, call, what);
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
