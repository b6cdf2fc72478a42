// The bodies of proceduray/vk/vulkan_instance.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/vulkan_instance.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk::detail {

PROCEDURAY_DECL void require_validation_layer() {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> available(count);
  vkEnumerateInstanceLayerProperties(&count, available.data());
  const bool found = std::any_of(available.begin(), available.end(), [](const VkLayerProperties& l) {
    return std::strcmp(l.layerName, validation_layer) == 0;
  });
  if (!found) {
    throw EnvironmentError(
        "Context: validation was asked for but VK_LAYER_KHRONOS_validation is not installed; "
        "install it (apt-get install vulkan-validationlayers) or set ContextOptions::validation = false");
  }
}

}  // namespace proceduray::vk::detail

namespace proceduray::vk {

PROCEDURAY_DECL VulkanInstance::VulkanInstance(const char* application_name, ValidationLog* log) {
  auto app = make<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = application_name;
  app.pEngineName = "proceduray";
  app.apiVersion = VK_API_VERSION_1_2;

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  auto messenger = make<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
  if (log != nullptr) {
    detail::require_validation_layer();
    layers.push_back(detail::validation_layer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    messenger = log->messenger_info();
  }
  auto info = make<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  info.pNext = log != nullptr ? &messenger : nullptr;  // also catches messages from instance creation
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkResult result = vkCreateInstance(&info, nullptr, &m_instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER) {
    throw NoRayTracingDevice(
        "Context: vkCreateInstance found no Vulkan driver (VK_ERROR_INCOMPATIBLE_DRIVER). On a machine without a "
        "GPU install Mesa >= 24.1 (Debian 12: apt-get install -t bookworm-backports mesa-vulkan-drivers; "
        "tools/setup.sh does this); on an NVIDIA GPU install its driver");
  }
  check(result, "vkCreateInstance");
  if (log == nullptr) return;
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(m_instance, "vkCreateDebugUtilsMessengerEXT"));
  const VkResult made = create(m_instance, &messenger, nullptr, &m_messenger);
  if (made != VK_SUCCESS) release();  // a constructor that throws runs no destructor
  check(made, "vkCreateDebugUtilsMessengerEXT");
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
