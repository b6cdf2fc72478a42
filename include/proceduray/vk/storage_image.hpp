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

#include "proceduray/vk/storage_image-inl.hpp"  // the bodies (config.hpp)
