// The bodies of proceduray/image/texture_data.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/image/texture_data.hpp"

#if PROCEDURAY_BODIES
#include <proceduray/error.hpp>

#include <stb_image.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>

namespace proceduray {
namespace detail {

/// Channels 1..4 of `count` texels of T into RGBA: grey fills RGB, a missing alpha is `one`.
template <class T>
std::vector<std::byte> expand_rgba(std::span<const T> in, std::uint32_t channels, std::size_t count, T one) {
  std::vector<std::byte> out(count * 4 * sizeof(T));
  T* o = reinterpret_cast<T*>(out.data());
  for (std::size_t i = 0; i < count; ++i) {
    const T* p = in.data() + i * channels;
    const T r = p[0], g = channels >= 3 ? p[1] : p[0], b = channels >= 3 ? p[2] : p[0];
    const T a = channels == 2 ? p[1] : channels == 4 ? p[3] : one;
    o[4 * i] = r;
    o[4 * i + 1] = g;
    o[4 * i + 2] = b;
    o[4 * i + 3] = a;
  }
  return out;
}

template <class T>
TextureData texture_from(std::uint32_t width, std::uint32_t height, std::uint32_t channels, std::span<const T> pixels,
                         TexelFormat format, T one) {
  if (channels < 1 || channels > 4) {
    throw UsageError("TextureData::from_pixels: " + std::to_string(channels) + " channels; a texture takes 1 (grey), "
                     "2 (grey, alpha), 3 (RGB) or 4 (RGBA): convert the pixels to one of these");
  }
  const std::size_t count = std::size_t{width} * height;
  if (width == 0 || height == 0 || pixels.size() != count * channels) {
    throw UsageError("TextureData::from_pixels: " + std::to_string(pixels.size()) + " values for " +
                     std::to_string(width) + "x" + std::to_string(height) + " texels of " + std::to_string(channels) +
                     " channels (need " + std::to_string(count * channels) + ", and a size of at least 1x1); give "
                     "width * height * channels values");
  }
  return {width, height, 1, format, format == TexelFormat::rgba8, expand_rgba(pixels, channels, count, one)};
}

}  // namespace detail

PROCEDURAY_DECL TextureData TextureData::from_pixels(std::uint32_t width, std::uint32_t height, std::uint32_t channels,
                                            std::span<const std::uint8_t> pixels) {
  return detail::texture_from<std::uint8_t>(width, height, channels, pixels, TexelFormat::rgba8, 255);
}

PROCEDURAY_DECL TextureData TextureData::from_pixels(std::uint32_t width, std::uint32_t height, std::uint32_t channels,
                                            std::span<const float> pixels) {
  return detail::texture_from<float>(width, height, channels, pixels, TexelFormat::rgba32f, 1.0f);
}

PROCEDURAY_DECL TextureData load_texture(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw EnvironmentError("load_texture: '" + name + "' is not a file (missing, or a folder); check the path");
  }
  // Read once: stb's file functions would open it twice (once to tell HDR from the rest).
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto* bytes = reinterpret_cast<const stbi_uc*>(file.data());
  const int size = static_cast<int>(file.size());
  int w = 0, h = 0, channels = 0;
  const bool hdr = stbi_is_hdr_from_memory(bytes, size) != 0;
  // stb converts to four channels as it decodes; the file's own count comes back in `channels`.
  std::unique_ptr<void, void (*)(void*)> data(
      hdr ? static_cast<void*>(stbi_loadf_from_memory(bytes, size, &w, &h, &channels, 4))
          : static_cast<void*>(stbi_load_from_memory(bytes, size, &w, &h, &channels, 4)),
      stbi_image_free);
  if (!data) {
    const char* reason = stbi_failure_reason();
    throw EnvironmentError("load_texture: cannot decode '" + name + "' (" + (reason ? reason : "unknown reason") +
                           "); give a PNG, JPEG or Radiance HDR file");
  }
  TextureData t{static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h), 1,
                hdr ? TexelFormat::rgba32f : TexelFormat::rgba8, !hdr, {}};
  t.pixels.resize(t.face_bytes());
  std::memcpy(t.pixels.data(), data.get(), t.pixels.size());
  return t;
}

PROCEDURAY_DECL TextureData make_cube(std::span<const TextureData> faces) {
  if (faces.size() != 6) {
    throw UsageError("make_cube: " + std::to_string(faces.size()) + " faces; a cube map has six (+X, -X, +Y, -Y, +Z, -Z)");
  }
  const TextureData& first = faces[0];
  for (std::size_t i = 0; i < 6; ++i) {
    const TextureData& f = faces[i];
    if (f.faces != 1 || f.width != f.height || f.width != first.width || f.format != first.format ||
        f.srgb != first.srgb) {
      throw UsageError("make_cube: face " + std::to_string(i) + " is " + std::to_string(f.width) + "x" +
                       std::to_string(f.height) + (f.format == TexelFormat::rgba8 ? " rgba8" : " rgba32f") +
                       (f.faces != 1 ? " and itself a cube" : "") + ", face 0 is " + std::to_string(first.width) + "x" +
                       std::to_string(first.height) + (first.format == TexelFormat::rgba8 ? " rgba8" : " rgba32f") +
                       "; cube faces are square 2D textures of one size, format and colour space");
    }
  }
  TextureData cube{first.width, first.height, 6, first.format, first.srgb, {}};
  cube.pixels.reserve(6 * first.face_bytes());
  for (const TextureData& f : faces) cube.pixels.insert(cube.pixels.end(), f.pixels.begin(), f.pixels.end());
  return cube;
}

PROCEDURAY_DECL TextureData load_cube(const std::array<std::filesystem::path, 6>& paths) {
  std::vector<TextureData> faces;
  for (const auto& p : paths) faces.push_back(load_texture(p));
  return make_cube(faces);
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
