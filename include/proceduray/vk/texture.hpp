// A texture on the device: the image (2D or cube) with its mip chain made by successive halving,
// its view and its sampler, ready for a combined-image-sampler binding (Renderer::set_texture).
//
//   proceduray::vk::Texture ground(ctx, proceduray::load_texture("ground.png"));   // linear, repeat, mips
//   proceduray::vk::Texture sky(ctx, proceduray::load_cube(faces), {.wrap = proceduray::TextureWrap::clamp});
//   ground.view(); ground.sampler(); ground.mip_levels();
//
// RGBA8 texels are sampled as sRGB colour when TextureData::srgb (the sampler returns linear
// values), RGBA32F as they are. A side past the device's maxImageDimension2D (maxImageDimensionCube
// for cube maps) throws DeviceLimitError naming both; a format the device cannot sample, blit or
// filter linearly throws DeviceLimitError with the setting to change. The upload waits.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/image/texture_data.hpp>
#include <proceduray/vk/buffer.hpp>
#include <proceduray/vk/context.hpp>
#include <proceduray/vk/handle.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string_view>

namespace proceduray::vk {

/// The Vulkan format a texture's texels are uploaded as.
PROCEDURAY_DECL VkFormat texture_format(const TextureData& data);

/// A sampled image with its mips, view and sampler.
class Texture {
 public:
  /// Uploads `data` and makes its mips (SamplerDesc::mipmaps) and sampler; `op` names the call in messages.
  Texture(const Context& ctx, const TextureData& data, const SamplerDesc& sampler = {},
          std::string_view op = "vk::Texture");

  VkImageView view() const noexcept { return m_view.get(); }
  VkSampler sampler() const noexcept { return m_sampler.get(); }
  std::uint32_t width() const noexcept { return m_width; }
  std::uint32_t height() const noexcept { return m_height; }
  std::uint32_t mip_levels() const noexcept { return m_levels; }
  bool cube() const noexcept { return m_layers == 6; }

 private:
  void upload(const Context& ctx, const TextureData& data, VkImage image);

  std::uint32_t m_width = 0, m_height = 0, m_levels = 1, m_layers = 1;
  DeviceHandle<VkDeviceMemory> m_memory;  // declared first: the image goes before its memory
  DeviceHandle<VkImage> m_image;
  DeviceHandle<VkImageView> m_view;
  DeviceHandle<VkSampler> m_sampler;
};

}  // namespace proceduray::vk

#include "proceduray/vk/texture-inl.hpp"  // the bodies (config.hpp)
