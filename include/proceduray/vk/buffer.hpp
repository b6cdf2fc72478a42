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

#if PROCEDURAY_BODIES

namespace proceduray::vk {

PROCEDURAY_DECL Buffer::Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, Memory memory)
    : m_size(size) {
  if (size == 0) {
    throw UsageError("Buffer: size 0 requested; Vulkan buffers need at least one byte");
  }
  auto info = make<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer raw = VK_NULL_HANDLE;
  check(vkCreateBuffer(ctx.device(), &info, nullptr, &raw), "vkCreateBuffer", std::to_string(size) + " bytes");
  m_buffer = own(ctx.device(), raw, vkDestroyBuffer);

  VkMemoryRequirements needs{};
  vkGetBufferMemoryRequirements(ctx.device(), raw, &needs);
  const VkMemoryPropertyFlags flags = memory == host_visible
                                          ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                                      : memory == host_cached ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT
                                                              : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  auto address_flags = make<VkMemoryAllocateFlagsInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO);
  address_flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  const bool wants_address = (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) != 0;
  auto alloc = make<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, wants_address ? &address_flags : nullptr);
  alloc.allocationSize = needs.size;
  alloc.memoryTypeIndex = memory == host_cached
                             ? ctx.memory_type(needs.memoryTypeBits, flags, VK_MEMORY_PROPERTY_HOST_CACHED_BIT)
                             : ctx.memory_type(needs.memoryTypeBits, flags);
  m_coherent = (ctx.memory_flags(alloc.memoryTypeIndex) & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
  m_device = ctx.device();
  VkDeviceMemory mem = VK_NULL_HANDLE;
  check(vkAllocateMemory(ctx.device(), &alloc, nullptr, &mem), "vkAllocateMemory", std::to_string(needs.size) + " bytes");
  m_memory = own(ctx.device(), mem, vkFreeMemory);
  check(vkBindBufferMemory(ctx.device(), raw, mem, 0), "vkBindBufferMemory");
  if (memory != device_local) {
    check(vkMapMemory(ctx.device(), mem, 0, VK_WHOLE_SIZE, 0, &m_mapped), "vkMapMemory");
  }
  if (wants_address) {
    auto where = make<VkBufferDeviceAddressInfo>(VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO);
    where.buffer = raw;
    m_address = vkGetBufferDeviceAddress(ctx.device(), &where);
  }
}

PROCEDURAY_DECL VkDeviceAddress Buffer::address() const {
  if (m_address == 0) {
    throw UsageError("Buffer::address: the buffer was created without VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT; "
                     "add it to the usage flags");
  }
  return m_address;
}

PROCEDURAY_DECL void Buffer::invalidate() const {
  if (m_coherent || m_mapped == nullptr) return;
  auto range = make<VkMappedMemoryRange>(VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE);
  range.memory = m_memory.get();
  range.size = VK_WHOLE_SIZE;
  check(vkInvalidateMappedMemoryRanges(m_device, 1, &range), "vkInvalidateMappedMemoryRanges");
}

PROCEDURAY_DECL void Buffer::write(std::span<const std::byte> bytes, VkDeviceSize offset) {
  if (m_mapped == nullptr) {
    throw UsageError("Buffer::write: the buffer is device-local; create it with Buffer::host_visible to write it "
                     "from the host");
  }
  if (offset > m_size || bytes.size() > m_size - offset) {
    throw UsageError("Buffer::write: " + std::to_string(bytes.size()) + " bytes at offset " +
                     std::to_string(offset) + " overrun the buffer's " + std::to_string(m_size) + " bytes");
  }
  std::memcpy(static_cast<std::byte*>(m_mapped) + offset, bytes.data(), bytes.size());
  if (!m_coherent) {
    auto range = make<VkMappedMemoryRange>(VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE);
    range.memory = m_memory.get();
    range.size = VK_WHOLE_SIZE;
    check(vkFlushMappedMemoryRanges(m_device, 1, &range), "vkFlushMappedMemoryRanges");
  }
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
