// The bodies of proceduray/vk/buffer.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/buffer.hpp"

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
  m_buffer = own(ctx, raw, vkDestroyBuffer);

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
  m_memory = own(ctx, mem, vkFreeMemory);
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
