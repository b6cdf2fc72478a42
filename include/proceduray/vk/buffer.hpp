// Buffers with their own memory and, when asked, a device address.
//
//   using proceduray::vk::Buffer;
//   Buffer aabbs(ctx, sizeof(boxes), VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
//                                    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, Buffer::host_visible);
//   aabbs.write(boxes);          // host-visible buffers are written in place
//   aabbs.address();             // VkDeviceAddress for builds and shaders
//
//   Buffer readback(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, Buffer::host_cached);
//   // ... copy into it on the device, wait ...
//   readback.invalidate();       // then read readback.data()
//
// Memory is host-visible and coherent unless Buffer::device_local or Buffer::host_cached is asked
// for; every buffer gets VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT when its usage needs an address.
// host_cached is for what the host reads: uncached (write-combined) memory is read at a fraction
// of memory speed, so a 16 MiB frame took 55-75 ms to copy out of it on an H200 host.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/vk/context.hpp>

#include <cstring>
#include <span>
#include <stdexcept>
#include <string>

namespace proceduray::vk {

/// A VkBuffer bound to its own VkDeviceMemory.
class Buffer {
 public:
  /// Where the memory lives. host_cached: host-visible, cached where the device has such memory
  /// (for readback; call invalidate() before reading), else coherent.
  enum Memory { device_local, host_visible, host_cached };

  Buffer() = default;
  /// Creates a buffer of `size` bytes (must be > 0) with `usage`; device addresses are enabled when usage asks.
  Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, Memory memory = host_visible);

  VkBuffer get() const noexcept { return m_buffer.get(); }
  VkDeviceSize size() const noexcept { return m_size; }
  /// The buffer's device address; throws if it was made without VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT.
  VkDeviceAddress address() const;
  /// Mapped pointer of a host-visible buffer, else nullptr.
  void* data() const noexcept { return m_mapped; }
  /// Makes device writes visible to data() in non-coherent memory (after the fence of the copy);
  /// nothing to do for coherent memory.
  void invalidate() const;

  /// Copies `bytes` to `offset`; throws UsageError past the end or for device-local memory.
  void write(std::span<const std::byte> bytes, VkDeviceSize offset = 0);
  template <class T>
  void write(std::span<const T> values, VkDeviceSize offset = 0) {
    write(std::as_bytes(values), offset);
  }

 private:
  DeviceHandle<VkDeviceMemory> m_memory;  // declared before the buffer: the buffer is destroyed first
  DeviceHandle<VkBuffer> m_buffer;
  VkDeviceSize m_size = 0;
  VkDeviceAddress m_address = 0;
  void* m_mapped = nullptr;
  bool m_coherent = true;
  VkDevice m_device = VK_NULL_HANDLE;
};

}  // namespace proceduray::vk

#include "proceduray/vk/buffer-inl.hpp"  // the bodies (config.hpp)
