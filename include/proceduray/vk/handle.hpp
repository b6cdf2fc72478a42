// Move-only ownership of Vulkan device objects: std::unique_ptr with the destroy call as deleter.
//
//   proceduray::vk::DeviceHandle<VkBuffer> buffer = proceduray::vk::own(device, raw, vkDestroyBuffer);
//   buffer.get();   // the VkBuffer; destroyed when `buffer` goes out of scope
//
// The library's objects use own(ctx, raw, destroy) (context.hpp): that handle holds a share of
// its Context's device, as Vulkan-Hpp's RAII children hold their parent, so the device goes only
// after the last object made on it, whatever order the caller destroys things in. own(device, ...)
// holds none: for the Context's own objects, which the device must not wait for.
// Members of a class holding several handles are destroyed in reverse declaration order,
// so declare what others depend on (memory) before them (the buffer bound to it).
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <type_traits>
#include <utility>

namespace proceduray::vk {

/// Destroy function shape shared by vkDestroyBuffer, vkFreeMemory, vkDestroyPipeline, ...
template <class Handle>
using DestroyFn = void (*)(VkDevice, Handle, const VkAllocationCallbacks*);

/// Deleter that calls the destroy function with the device the handle was made on. `device_owner`
/// (a share of the device's Context, or empty) is released after the call, with the deleter.
template <class Handle>
struct DeviceDeleter {
  VkDevice device = VK_NULL_HANDLE;
  DestroyFn<Handle> destroy = nullptr;
  std::shared_ptr<const void> device_owner;
  void operator()(Handle handle) const noexcept {
    if (handle != VK_NULL_HANDLE && destroy != nullptr) destroy(device, handle, nullptr);
  }
};

/// An owned Vulkan device object; null when moved from.
template <class Handle>
using DeviceHandle = std::unique_ptr<std::remove_pointer_t<Handle>, DeviceDeleter<Handle>>;

/// Takes ownership of `handle`, destroyed later with `destroy(device, handle, nullptr)`; keeps
/// `device_owner` (if any) alive until then.
template <class Handle>
DeviceHandle<Handle> own(VkDevice device, Handle handle, DestroyFn<Handle> destroy,
                         std::shared_ptr<const void> device_owner = {}) {
  return DeviceHandle<Handle>(handle, DeviceDeleter<Handle>{device, destroy, std::move(device_owner)});
}

}  // namespace proceduray::vk
