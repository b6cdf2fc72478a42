// Vulkan info structs zeroed, with sType (and pNext) set: one line instead of three.
//
//   auto info = proceduray::vk::make<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
//   auto v12  = proceduray::vk::make<VkPhysicalDeviceVulkan12Features>(
//       VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &rt_features);
#pragma once

#include <vulkan/vulkan.h>

namespace proceduray::vk {

/// A value-initialised T with sType = `type` and pNext = `next`.
template <class T>
T make(VkStructureType type, const void* next = nullptr) {
  T value{};
  value.sType = type;
  value.pNext = const_cast<decltype(value.pNext)>(next);  // properties chains use void*, create infos const void*
  return value;
}

}  // namespace proceduray::vk
