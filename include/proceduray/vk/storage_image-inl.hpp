// The bodies of proceduray/vk/storage_image.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/storage_image.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL std::uint32_t storage_pixel_bytes(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT: return 4;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_UINT: return 16;
    default: return 0;
  }
}

PROCEDURAY_DECL StorageImage::StorageImage(const Context& ctx, std::uint32_t width, std::uint32_t height, VkFormat format,
                                           Init init)
    : m_ctx(&ctx), m_width(width), m_height(height), m_format(format) {
  if (storage_pixel_bytes(format) == 0) {
    throw UsageError("StorageImage: format " + std::to_string(static_cast<int>(format)) +
                     " is not one it takes; use VK_FORMAT_R8G8B8A8_UNORM, R32_SFLOAT, R32_UINT, "
                     "R32G32B32A32_SFLOAT or R32G32B32A32_UINT");
  }
  const std::uint32_t limit = ctx.properties().limits.maxImageDimension2D;
  if (width == 0 || height == 0 || width > limit || height > limit) {
    const std::string message = "StorageImage: size " + std::to_string(width) + "x" + std::to_string(height) +
                                " is outside 1.." + std::to_string(limit) + " (maxImageDimension2D of " + ctx.name() +
                                "); give a size in that range";
    if (width == 0 || height == 0) throw UsageError(message);
    throw DeviceLimitError(message);
  }
  auto info = make<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  check(vkCreateImage(ctx.device(), &info, nullptr, &image), "vkCreateImage");
  m_image = own(ctx, image, vkDestroyImage);

  VkMemoryRequirements needs{};
  vkGetImageMemoryRequirements(ctx.device(), image, &needs);
  auto alloc = make<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  alloc.allocationSize = needs.size;
  alloc.memoryTypeIndex = ctx.memory_type(needs.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  check(vkAllocateMemory(ctx.device(), &alloc, nullptr, &memory), "vkAllocateMemory", "storage image");
  m_memory = own(ctx, memory, vkFreeMemory);
  // m_memory is declared first so the image is destroyed before its memory is freed.
  check(vkBindImageMemory(ctx.device(), image, memory, 0), "vkBindImageMemory");

  auto view_info = make<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  view_info.image = image;
  view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view_info.format = format;
  view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  check(vkCreateImageView(ctx.device(), &view_info, nullptr, &view), "vkCreateImageView");
  m_view = own(ctx, view, vkDestroyImageView);

  if (init == now) ctx.submit([&](VkCommandBuffer cmd) { record_init(cmd); });
}

PROCEDURAY_DECL void StorageImage::record_init(VkCommandBuffer cmd) {
  if (m_initialised) return;
  transition(cmd, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, 0,
             VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
             VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR | VK_PIPELINE_STAGE_TRANSFER_BIT);
  m_initialised = true;
}

PROCEDURAY_DECL void StorageImage::record_copy(VkCommandBuffer cmd, const Buffer& buffer, VkDeviceSize offset) const {
  if (offset > buffer.size() || bytes() > buffer.size() - offset) {
    throw UsageError("StorageImage::record_copy: " + std::to_string(bytes()) + " bytes at offset " +
                     std::to_string(offset) + " overrun the buffer's " + std::to_string(buffer.size()) +
                     " bytes; give a buffer of at least width * height * pixel bytes");
  }
  // GENERAL -> TRANSFER_SRC for the copy (the layout copies are fast from), then back for the next trace.
  transition(cmd, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
             VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
             VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR | VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkBufferImageCopy copy{};
  copy.bufferOffset = offset;
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {m_width, m_height, 1};
  vkCmdCopyImageToBuffer(cmd, m_image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.get(), 1, &copy);
  transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_TRANSFER_READ_BIT,
             VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
             VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR | VK_PIPELINE_STAGE_TRANSFER_BIT);
  auto to_host = make<VkBufferMemoryBarrier>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER);
  to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  to_host.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  to_host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  to_host.buffer = buffer.get();
  to_host.offset = offset;
  to_host.size = bytes();
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &to_host, 0,
                       nullptr);
}

PROCEDURAY_DECL void StorageImage::transition(VkCommandBuffer cmd, VkImageLayout from, VkImageLayout to, VkAccessFlags src_access,
                                              VkAccessFlags dst_access, VkPipelineStageFlags src_stage,
                                              VkPipelineStageFlags dst_stage) const {
  auto barrier = make<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = m_image.get();
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

PROCEDURAY_DECL void StorageImage::record_clear(VkCommandBuffer cmd, const VkClearColorValue& value) const {
  // Earlier traces' writes before the clear; the clear before this trace's writes.
  transition(cmd, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_SHADER_READ_BIT,
             VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT);
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd, m_image.get(), VK_IMAGE_LAYOUT_GENERAL, &value, 1, &range);
  transition(cmd, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_TRANSFER_WRITE_BIT,
             VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
             VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);
}

PROCEDURAY_DECL std::vector<std::uint8_t> StorageImage::read() const {
  if (!m_initialised) {
    throw UsageError("StorageImage::read: the image was made StorageImage::recorded and its record_init() was "
                     "never submitted; record it before the first trace");
  }
  // Made once, host-cached: a renderer reads its frames back every frame.
  if (!m_staging) m_staging = std::make_unique<Buffer>(*m_ctx, bytes(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, Buffer::host_cached);
  m_ctx->submit([&](VkCommandBuffer cmd) { record_copy(cmd, *m_staging, 0); });
  m_staging->invalidate();
  const auto* data = static_cast<const std::uint8_t*>(m_staging->data());
  return std::vector<std::uint8_t>(data, data + bytes());
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
