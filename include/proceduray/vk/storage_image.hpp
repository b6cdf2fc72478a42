// A storage image that ray-tracing shaders write and the host reads back: RGBA8 colour by
// default, or one of the 32-bit formats of per-pixel outputs (scene/outputs.hpp).
//
//   proceduray::vk::StorageImage image(ctx, 640, 480);   // in VK_IMAGE_LAYOUT_GENERAL
//   set.write(1, image.view());
//   // ... trace ...
//   std::vector<std::uint8_t> rgba = image.read();        // width * height * 4 bytes, rows top to bottom
//   proceduray::vk::StorageImage depth(ctx, 640, 480, VK_FORMAT_R32_SFLOAT);
//   ctx.submit([&](VkCommandBuffer cmd) { depth.record_clear(cmd, {.float32 = {-1.0f}}); });
//   std::vector<float> t = depth.read_as<float>();        // width * height floats
//
//   proceduray::vk::StorageImage later(ctx, 640, 480, VK_FORMAT_R8G8B8A8_UNORM, proceduray::vk::StorageImage::recorded);
//   later.record_init(frame_cmd);                          // its layout transition, in your frame (no wait)
//   later.record_copy(frame_cmd, readback, 0);             // after a trace: into a buffer, no second submit
//
// A zero size throws proceduray::UsageError, one past maxImageDimension2D proceduray::DeviceLimitError,
// a format other than those five UsageError.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/vk/buffer.hpp>

#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

namespace proceduray::vk {

/// Bytes per pixel of the formats a StorageImage takes; 0 for any other.
PROCEDURAY_DECL std::uint32_t storage_pixel_bytes(VkFormat format);

/// A 2D image in the general layout, with a view for storage writes (formats: storage_pixel_bytes).
class StorageImage {
 public:
  /// How the image reaches the general layout: `now` submits the transition and waits;
  /// `recorded` leaves it to record_init() in the caller's command buffer (a renderer's frame).
  enum Init { now, recorded };
  StorageImage(const Context& ctx, std::uint32_t width, std::uint32_t height, VkFormat format = VK_FORMAT_R8G8B8A8_UNORM,
               Init init = now);

  VkImage get() const noexcept { return m_image.get(); }
  VkImageView view() const noexcept { return m_view.get(); }
  std::uint32_t width() const noexcept { return m_width; }
  std::uint32_t height() const noexcept { return m_height; }
  VkFormat format() const noexcept { return m_format; }
  /// Copies the image to the host (waits for the queue): width * height pixels, row by row, as bytes.
  std::vector<std::uint8_t> read() const;
  /// The same as values of T (float or std::uint32_t), channels of a pixel consecutive.
  template <class T>
  std::vector<T> read_as() const {
    static_assert(sizeof(T) == 4, "StorageImage::read_as: 32-bit channels (float, std::uint32_t)");
    const std::vector<std::uint8_t> bytes = read();
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
  }
  /// Records a clear of the whole image to `value` (float32 or uint32 as the format is), with
  /// barriers from and to ray-tracing shader writes; the image stays in the general layout.
  void record_clear(VkCommandBuffer cmd, const VkClearColorValue& value) const;
  /// Records the transition from the undefined to the general layout (an image made `recorded`),
  /// once: later calls record nothing. Whatever the image held is discarded.
  void record_init(VkCommandBuffer cmd);
  /// Bytes of the whole image, tightly packed (width * height * pixel bytes).
  VkDeviceSize bytes() const noexcept { return VkDeviceSize{m_width} * m_height * storage_pixel_bytes(m_format); }
  /// Records, after the trace that writes the image, a copy of it to `buffer` at `offset` and the
  /// barrier that makes it visible to the host once the submit's fence signals. The image is back
  /// in the general layout afterwards.
  void record_copy(VkCommandBuffer cmd, const Buffer& buffer, VkDeviceSize offset) const;

 private:
  void transition(VkCommandBuffer cmd, VkImageLayout from, VkImageLayout to, VkAccessFlags src_access,
                  VkAccessFlags dst_access, VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage) const;

  const Context* m_ctx;
  std::uint32_t m_width;
  std::uint32_t m_height;
  VkFormat m_format;
  DeviceHandle<VkDeviceMemory> m_memory;
  DeviceHandle<VkImage> m_image;
  DeviceHandle<VkImageView> m_view;
  mutable std::unique_ptr<Buffer> m_staging;  // readback target, made at the first read()
  bool m_initialised = false;
};

}  // namespace proceduray::vk

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
  m_image = own(ctx.device(), image, vkDestroyImage);

  VkMemoryRequirements needs{};
  vkGetImageMemoryRequirements(ctx.device(), image, &needs);
  auto alloc = make<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  alloc.allocationSize = needs.size;
  alloc.memoryTypeIndex = ctx.memory_type(needs.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  check(vkAllocateMemory(ctx.device(), &alloc, nullptr, &memory), "vkAllocateMemory", "storage image");
  m_memory = own(ctx.device(), memory, vkFreeMemory);
  // m_memory is declared first so the image is destroyed before its memory is freed.
  check(vkBindImageMemory(ctx.device(), image, memory, 0), "vkBindImageMemory");

  auto view_info = make<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  view_info.image = image;
  view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view_info.format = format;
  view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  check(vkCreateImageView(ctx.device(), &view_info, nullptr, &view), "vkCreateImageView");
  m_view = own(ctx.device(), view, vkDestroyImageView);

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
