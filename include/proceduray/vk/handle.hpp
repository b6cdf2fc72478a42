// Move-only ownership of Vulkan device objects: std::unique_ptr with the destroy call as deleter.
//
//   proceduray::vk::DeviceHandle<VkBuffer> buffer = proceduray::vk::own(device, raw, vkDestroyBuffer);
//   buffer.get();   // the VkBuffer; destroyed when `buffer` goes out of scope
//
// Members of a class holding several handles are destroyed in reverse declaration order,
// so declare what others depend on (memory) before them (the buffer bound to it).
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <type_traits>

namespace proceduray::vk {

/// Destroy function shape shared by vkDestroyBuffer, vkFreeMemory, vkDestroyPipeline, ...
template <class Handle>
using DestroyFn = void (*)(VkDevice, Handle, const VkAllocationCallbacks*);

/// Deleter that calls the destroy function with the device the handle was made on.
template <class Handle>
struct DeviceDeleter {
  VkDevice device = VK_NULL_HANDLE;
  DestroyFn<Handle> destroy = nullptr;
  void operator()(Handle handle) const noexcept {
    if (handle != VK_NULL_HANDLE && destroy != nullptr) destroy(device, handle, nullptr);
  }
};

/// An owned Vulkan device object; null when moved from.
template <class Handle>
using DeviceHandle = std::unique_ptr<std::remove_pointer_t<Handle>, DeviceDeleter<Handle>>;

/// Takes ownership of `handle`, destroyed later with `destroy(device, handle, nullptr)`.
template <class Handle>
DeviceHandle<Handle> own(VkDevice device, Handle handle, DestroyFn<Handle> destroy) {
  return DeviceHandle<Handle>(handle, DeviceDeleter<Handle>{device, destroy});
}

}  // namespace proceduray::vk
