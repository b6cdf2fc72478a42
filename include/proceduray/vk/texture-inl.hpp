// The bodies of proceduray/vk/texture.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/texture.hpp"

#if PROCEDURAY_BODIES

namespace proceduray::vk {

PROCEDURAY_DECL VkFormat texture_format(const TextureData& data) {
  if (data.format == TexelFormat::rgba32f) return VK_FORMAT_R32G32B32A32_SFLOAT;
  return data.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
}

/// The format of `data`, after checking that it is well formed and that the device can take it at
/// `levels` mip levels with `sampler`; throws UsageError or DeviceLimitError naming `op`.
PROCEDURAY_DECL VkFormat checked_texture_format(const Context& ctx, const TextureData& data, const SamplerDesc& sampler,
                                                std::uint32_t levels, std::string_view op) {
  const std::string what = std::string(op) + ": a " + std::to_string(data.width) + "x" + std::to_string(data.height) +
                           (data.cube() ? " cube map" : " texture");
  if (data.width == 0 || data.height == 0 || (data.faces != 1 && data.faces != 6) ||
      data.pixels.size() != data.faces * data.face_bytes()) {
    throw UsageError(what + " with " + std::to_string(data.faces) + " faces and " + std::to_string(data.pixels.size()) +
                     " bytes of pixels is malformed; make it with load_texture, TextureData::from_pixels or make_cube");
  }
  if (data.format == TexelFormat::rgba32f) {  // filtering and mips spread one NaN texel over its neighbours
    const std::size_t values = data.pixels.size() / sizeof(float);
    for (std::size_t i = 0; i < values; ++i) {
      float v;
      std::memcpy(&v, data.pixels.data() + i * sizeof(float), sizeof v);
      if (std::isfinite(v)) continue;
      const std::size_t texel = i / 4, per_face = std::size_t{data.width} * data.height;
      std::ostringstream m;
      m << what << " has texel (" << texel % per_face % data.width << ", " << texel % per_face / data.width << ")";
      if (data.cube()) m << " of face " << texel / per_face;
      m << ", channel " << "RGBA"[i % 4] << ", = " << v << "; float texels must be finite: replace NaN and "
        << "infinities (clamp them) before the upload";
      throw UsageError(m.str());
    }
  }
  const VkPhysicalDeviceLimits& limits = ctx.properties().limits;
  const std::uint32_t limit = data.cube() ? limits.maxImageDimensionCube : limits.maxImageDimension2D;
  if (data.width > limit || data.height > limit) {
    throw DeviceLimitError(what + " is larger than " + ctx.name() + " allows (" +
                           (data.cube() ? "maxImageDimensionCube " : "maxImageDimension2D ") + std::to_string(limit) +
                           "); scale the image down to at most " + std::to_string(limit) + " texels a side");
  }
  const VkFormat format = texture_format(data);
  VkFormatProperties props{};
  vkGetPhysicalDeviceFormatProperties(ctx.physical_device(), format, &props);
  const VkFormatFeatureFlags have = props.optimalTilingFeatures;
  VkFormatFeatureFlags need = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
  if (levels > 1) need |= VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT;
  if (sampler.filter == TextureFilter::linear) need |= VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if ((have & need) != need) {
    throw DeviceLimitError(what + " in format " + std::to_string(static_cast<int>(format)) + " cannot be " +
                           ((have & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT) == 0 ? "sampled"
                            : (have & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) == 0 ? "filtered linearly"
                                                                                            : "blitted for mipmaps") +
                           " on " + ctx.name() + "; use TextureFilter::nearest, mipmaps = false, or RGBA8 texels");
  }
  return format;
}

PROCEDURAY_DECL Texture::Texture(const Context& ctx, const TextureData& data, const SamplerDesc& sampler,
                                 std::string_view op)
    : m_width(data.width), m_height(data.height), m_levels(sampler.mipmaps ? data.mip_levels() : 1),
      m_layers(data.faces) {
  const VkFormat format = checked_texture_format(ctx, data, sampler, m_levels, op);
  auto info = make<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  info.flags = data.cube() ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {data.width, data.height, 1};
  info.mipLevels = m_levels;
  info.arrayLayers = m_layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
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
  check(vkAllocateMemory(ctx.device(), &alloc, nullptr, &memory), "vkAllocateMemory", "texture");
  m_memory = own(ctx, memory, vkFreeMemory);
  check(vkBindImageMemory(ctx.device(), image, memory, 0), "vkBindImageMemory");
  upload(ctx, data, image);

  auto view_info = make<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  view_info.image = image;
  view_info.viewType = data.cube() ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_2D;
  view_info.format = format;
  view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, m_levels, 0, m_layers};
  VkImageView view = VK_NULL_HANDLE;
  check(vkCreateImageView(ctx.device(), &view_info, nullptr, &view), "vkCreateImageView");
  m_view = own(ctx, view, vkDestroyImageView);

  constexpr VkSamplerAddressMode modes[] = {VK_SAMPLER_ADDRESS_MODE_REPEAT, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                            VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT};
  const VkSamplerAddressMode mode = modes[static_cast<std::uint32_t>(sampler.wrap)];
  const bool linear = sampler.filter == TextureFilter::linear;
  auto s = make<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  s.magFilter = s.minFilter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  s.mipmapMode = linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  // A cube map's edges are seamless in Vulkan whatever the mode; clamp keeps faces from wrapping in 2D.
  s.addressModeU = s.addressModeV = s.addressModeW = data.cube() ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : mode;
  s.maxLod = static_cast<float>(m_levels);
  VkSampler handle = VK_NULL_HANDLE;
  check(vkCreateSampler(ctx.device(), &s, nullptr, &handle), "vkCreateSampler");
  m_sampler = own(ctx, handle, vkDestroySampler);
}

PROCEDURAY_DECL void Texture::upload(const Context& ctx, const TextureData& data, VkImage image) {
  Buffer staging(ctx, data.pixels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  staging.write(std::span<const std::byte>(data.pixels));
  auto barrier = [&](VkCommandBuffer cmd, std::uint32_t level, std::uint32_t levels, VkImageLayout from,
                     VkImageLayout to, VkAccessFlags src, VkAccessFlags dst, VkPipelineStageFlags src_stage,
                     VkPipelineStageFlags dst_stage) {
    auto b = make<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
    b.srcAccessMask = src;
    b.dstAccessMask = dst;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, levels, 0, m_layers};
    vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &b);
  };
  ctx.submit([&](VkCommandBuffer cmd) {
    barrier(cmd, 0, m_levels, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
            VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, m_layers};  // faces follow each other in the buffer
    copy.imageExtent = {m_width, m_height, 1};
    vkCmdCopyBufferToImage(cmd, staging.get(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    // Each level is the one above halved: read it as a blit source, write the next.
    std::int32_t w = static_cast<std::int32_t>(m_width), h = static_cast<std::int32_t>(m_height);
    for (std::uint32_t level = 1; level < m_levels; ++level) {
      barrier(cmd, level - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
              VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
              VK_PIPELINE_STAGE_TRANSFER_BIT);
      VkImageBlit blit{};
      blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, m_layers};
      blit.srcOffsets[1] = {w, h, 1};
      w = w > 1 ? w / 2 : 1;
      h = h > 1 ? h / 2 : 1;
      blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, m_layers};
      blit.dstOffsets[1] = {w, h, 1};
      vkCmdBlitImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                     &blit, VK_FILTER_LINEAR);
    }
    // Every level but the last is a blit source now; all become shader-readable.
    if (m_levels > 1) {
      barrier(cmd, 0, m_levels - 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
              VK_ACCESS_TRANSFER_READ_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
              VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);
    }
    barrier(cmd, m_levels - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
            VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);
  });
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
