// Texture pixels on the host, before any device sees them: read from PNG, JPEG or HDR files
// through stb_image (Debian's libstb), or made from pixels in memory; 2D or a cube of six faces;
// with the mip chain length they get on the device.
//
//   proceduray::TextureData ground = proceduray::load_texture("textures/ground.png");   // RGBA8, sRGB
//   proceduray::TextureData sky = proceduray::load_cube({"px.hdr", "nx.hdr", "py.hdr", "ny.hdr", "pz.hdr", "nz.hdr"});
//   std::vector<std::uint8_t> grey(16 * 16, 128);
//   proceduray::TextureData made = proceduray::TextureData::from_pixels(16, 16, 1, grey);   // 1 to 4 channels
//   ground.mip_levels();   // 1 + floor(log2(max(width, height)))
//   proceduray::SamplerDesc pixelated{.filter = proceduray::TextureFilter::nearest, .mipmaps = false};
//
// PNG and JPEG give 8-bit RGBA, treated as sRGB colour (TextureData::srgb; clear it for data such
// as normal maps); HDR files give 32-bit float RGBA, linear. Grey, grey+alpha and RGB are
// expanded to RGBA. Rows are top to bottom, as the files store them. A file that cannot be read
// or decoded throws EnvironmentError naming it and stb's reason; other bad input (a channel count
// outside 1..4, pixels that do not fill the size, cube faces of different or non-square sizes)
// throws UsageError naming the value and the fix. The device's size limit is checked when the
// texture is uploaded (vk/texture.hpp).
#pragma once

#include <proceduray/config.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace proceduray {

/// How texels are stored: 8-bit unsigned normalised or 32-bit float, four channels each.
enum class TexelFormat : std::uint32_t { rgba8, rgba32f };

/// How a sampler reads between texels, and past the edges.
enum class TextureFilter : std::uint32_t { linear, nearest };
enum class TextureWrap : std::uint32_t { repeat, clamp, mirror };

/// A texture's sampler: filter (also between mip levels), wrap, and whether the mip chain is made.
struct SamplerDesc {
  TextureFilter filter = TextureFilter::linear;
  TextureWrap wrap = TextureWrap::repeat;
  bool mipmaps = true;  ///< the full chain, made on the device by successive halving
};

/// Bytes of one texel.
constexpr std::uint32_t texel_bytes(TexelFormat f) { return f == TexelFormat::rgba8 ? 4 : 16; }

/// A 2D texture or a cube map's six faces, RGBA, rows top to bottom.
struct TextureData {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t faces = 1;                 ///< 1 (2D) or 6 (cube: +X, -X, +Y, -Y, +Z, -Z)
  TexelFormat format = TexelFormat::rgba8;
  bool srgb = true;                        ///< rgba8 only: colour in sRGB, read back linear by the sampler
  std::vector<std::byte> pixels;           ///< faces * height * width texels, face after face

  bool cube() const noexcept { return faces == 6; }
  /// Bytes of one face.
  std::size_t face_bytes() const noexcept { return std::size_t{width} * height * texel_bytes(format); }
  /// Levels of the full mip chain: 1 + floor(log2(max(width, height))).
  std::uint32_t mip_levels() const noexcept {
    std::uint32_t levels = 1;
    for (std::uint32_t size = width > height ? width : height; size > 1; size /= 2) ++levels;
    return levels;
  }

  /// A 2D texture from 8-bit pixels of 1 (grey), 2 (grey, alpha), 3 (RGB) or 4 (RGBA) channels,
  /// expanded to RGBA; throws UsageError for another channel count or a size the pixels do not fill.
  static TextureData from_pixels(std::uint32_t width, std::uint32_t height, std::uint32_t channels,
                                 std::span<const std::uint8_t> pixels);
  /// The same from 32-bit float pixels: a linear, rgba32f texture.
  static TextureData from_pixels(std::uint32_t width, std::uint32_t height, std::uint32_t channels,
                                 std::span<const float> pixels);
};

/// Reads a PNG, JPEG (rgba8, sRGB) or Radiance HDR (rgba32f) file; throws EnvironmentError.
PROCEDURAY_DECL TextureData load_texture(const std::filesystem::path& path);
/// Makes a cube map of six square 2D textures of one size and format, in +X, -X, +Y, -Y, +Z, -Z order.
PROCEDURAY_DECL TextureData make_cube(std::span<const TextureData> faces);
/// Reads six files (+X, -X, +Y, -Y, +Z, -Z) into a cube map.
PROCEDURAY_DECL TextureData load_cube(const std::array<std::filesystem::path, 6>& paths);

}  // namespace proceduray

#include "proceduray/image/texture_data-inl.hpp"  // the bodies (config.hpp)
