// The bodies of proceduray/image/png.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/image/png.hpp"

#if PROCEDURAY_BODIES
#include <stb_image_write.h>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace proceduray {

PROCEDURAY_DECL void check_writable(const std::filesystem::path& path) {
  std::error_code ec;
  const bool existed = std::filesystem::exists(path, ec);
  if (existed && std::filesystem::is_directory(path, ec)) {
    throw EnvironmentError("check_writable: '" + path.string() + "' is a directory; give a file path such as '" +
                           (path / "image.png").string() + "'");
  }
  std::FILE* f = std::fopen(path.string().c_str(), "ab");
  if (f == nullptr) {
    const int err = errno;
    throw EnvironmentError("check_writable: cannot write '" + path.string() + "': " + std::strerror(err) +
                           "; choose a path in an existing, writable folder");
  }
  std::fclose(f);
  if (!existed) std::filesystem::remove(path, ec);
}

PROCEDURAY_DECL void write_png(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                               std::span<const std::uint8_t> rgba) {
  if (rgba.size() != std::size_t{width} * height * 4) {
    throw UsageError("write_png: " + std::to_string(rgba.size()) + " bytes given for a " +
                     std::to_string(width) + "x" + std::to_string(height) + " RGBA8 image, which needs " +
                     std::to_string(std::size_t{width} * height * 4));
  }
  check_writable(path);
  if (stbi_write_png(path.string().c_str(), static_cast<int>(width), static_cast<int>(height), 4, rgba.data(),
                     static_cast<int>(width * 4)) == 0) {
    throw EnvironmentError("write_png: stb could not write '" + path.string() + "'; check free disk space");
  }
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
