// PNG output through stb_image_write (Debian's libstb).
//
//   proceduray::check_writable("out/hello.png");       // before rendering: fails early and clearly
//   proceduray::write_png("out/hello.png", 640, 480, rgba);
//
// A path that cannot be written throws proceduray::EnvironmentError, a wrong pixel count UsageError.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>

namespace proceduray {

/// Throws EnvironmentError unless `path` can be written (creates no file that was not there).
PROCEDURAY_DECL void check_writable(const std::filesystem::path& path);

/// Writes width x height RGBA8 pixels (rows top to bottom) as a PNG; throws when it cannot.
PROCEDURAY_DECL void write_png(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                               std::span<const std::uint8_t> rgba);

}  // namespace proceduray

#include "proceduray/image/png-inl.hpp"  // the bodies (config.hpp)
