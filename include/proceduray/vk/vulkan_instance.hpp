// The Vulkan instance a Context starts from: Vulkan 1.2 and, when validation is asked for, the
// Khronos validation layer with a messenger that collects (and prints) its warnings and errors.
//
//   proceduray::vk::ValidationLog log(/*print=*/false);
//   proceduray::vk::VulkanInstance instance("my_app", &log);   // nullptr: no validation layer
//   proceduray::vk::select_device(instance.get(), proceduray::vk::DevicePreference::automatic);
//   log.messages();          // what the layer reported so far (tests assert it is empty)
//
// Throws EnvironmentError when the layer is asked for but not installed, NoRayTracingDevice when
// there is no Vulkan driver at all. The log must outlive the instance (its messenger writes to it).
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/vk/device_selection.hpp>
#include <proceduray/vk/error.hpp>
#include <proceduray/vk/structs.hpp>

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace proceduray::vk {

namespace detail {
inline constexpr const char* validation_layer = "VK_LAYER_KHRONOS_validation";
}  // namespace detail

/// Warnings and errors the validation layer reported, collected by a messenger (thread-safe).
class ValidationLog {
 public:
  /// `print`: also write each message to stderr; default on.
  explicit ValidationLog(bool print = true) : m_print(print) {}
  ValidationLog(const ValidationLog&) = delete;
  ValidationLog& operator=(const ValidationLog&) = delete;

  /// The messages so far, oldest first.
  std::vector<std::string> messages() const {
    std::lock_guard lock(m_mutex);
    return m_messages;
  }
  /// A messenger description (warnings and errors of every type) that reports to this log.
  VkDebugUtilsMessengerCreateInfoEXT messenger_info() {
    auto info = make<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = &ValidationLog::on_message;
    info.pUserData = this;
    return info;
  }

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT type,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* self) {
    auto* log = static_cast<ValidationLog*>(self);
    std::string text = data->pMessage ? data->pMessage : "";
    // The loader's own general warnings (e.g. VK_INSTANCE_LAYERS also naming the validation layer
    // we enable) say nothing about the application's use of Vulkan: shown, not counted.
    const bool loader = type == VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT && data->pMessageIdName != nullptr &&
                        std::string_view(data->pMessageIdName) == "Loader Message";
    if (loader && severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
      if (log->m_print) std::fprintf(stderr, "proceduray: Vulkan loader note: %s\n", text.c_str());
      return VK_FALSE;
    }
    if (log->m_print) {
      std::fprintf(stderr, "proceduray: validation %s: %s\n",
                   severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning", text.c_str());
    }
    std::lock_guard lock(log->m_mutex);
    log->m_messages.push_back(std::move(text));
    return VK_FALSE;
  }

  bool m_print = true;
  mutable std::mutex m_mutex;
  std::vector<std::string> m_messages;
};

/// A VkInstance (Vulkan 1.2) and, with validation, its debug messenger; move-only.
class VulkanInstance {
 public:
  VulkanInstance() = default;
  /// Creates the instance; `log` non-null enables VK_LAYER_KHRONOS_validation reporting to it.
  VulkanInstance(const char* application_name, ValidationLog* log);
  VulkanInstance(VulkanInstance&& other) noexcept
      : m_instance(std::exchange(other.m_instance, VK_NULL_HANDLE)),
        m_messenger(std::exchange(other.m_messenger, VK_NULL_HANDLE)) {}
  VulkanInstance& operator=(VulkanInstance&& other) noexcept {
    if (this != &other) {
      release();
      m_instance = std::exchange(other.m_instance, VK_NULL_HANDLE);
      m_messenger = std::exchange(other.m_messenger, VK_NULL_HANDLE);
    }
    return *this;
  }
  ~VulkanInstance() { release(); }

  VkInstance get() const noexcept { return m_instance; }
  /// True when the validation layer is on and reporting.
  bool validation_enabled() const noexcept { return m_messenger != VK_NULL_HANDLE; }

 private:
  void release() noexcept {
    if (m_messenger != VK_NULL_HANDLE) {
      auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(m_instance, "vkDestroyDebugUtilsMessengerEXT"));
      if (destroy != nullptr) destroy(m_instance, m_messenger, nullptr);
      m_messenger = VK_NULL_HANDLE;
    }
    if (m_instance != VK_NULL_HANDLE) {
      vkDestroyInstance(m_instance, nullptr);
      m_instance = VK_NULL_HANDLE;
    }
  }

  VkInstance m_instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT m_messenger = VK_NULL_HANDLE;
};

namespace detail {

/// Throws EnvironmentError when VK_LAYER_KHRONOS_validation is not installed.
PROCEDURAY_DECL void require_validation_layer();

}  // namespace detail

}  // namespace proceduray::vk

#include "proceduray/vk/vulkan_instance-inl.hpp"  // the bodies (config.hpp)
