// Command-line options shared by the examples (size, frames, output, device, cache,
// validation), parsed by CLI11 (Debian: libcli11-dev); an example adds its own options.
//
//   examples::Options o = examples::parse(argc, argv, "02_paper_scene", {.width = 1024, .height = 768});
//   if (o.exit) return *o.exit;   // --help printed, or a bad option reported (status 2)
//   bool bench = false;            // an example's own option:
//   o = examples::parse(argc, argv, "03_d3d12_scene", {}, [&](CLI::App& app) { app.add_flag("--bench", bench); });
#pragma once

#include "paths.hpp"

#include <proceduray/vk/context.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace examples {

struct Options {
  std::uint32_t width = 640;
  std::uint32_t height = 360;
  std::uint32_t frames = 1;
  std::filesystem::path out;  ///< default: <program>.png
  proceduray::vk::DevicePreference device = proceduray::vk::DevicePreference::automatic;
  bool validation = false;
  std::filesystem::path cache;  ///< pipeline cache file; default: the cache folder's
  std::optional<int> exit;      ///< set when the program should stop with this code
};

/// Parses the shared options over `defaults`, and an example's own through `extra`. A bad
/// option prints "<program>: <what and the fix>" and sets exit to 2; --help sets it to 0.
inline Options parse(int argc, char** argv, const char* program, Options defaults,
                     const std::function<void(CLI::App&)>& extra = {}) {
  Options o = defaults;
  if (o.out.empty()) o.out = std::string(program) + ".png";
  CLI::App app{std::string(program) + ": a Proceduray example", program};
  std::string size = std::to_string(o.width) + "x" + std::to_string(o.height);
  std::string device = "auto";
  app.add_option("--size", size, "image size WxH")->capture_default_str();
  app.add_option("--frames", o.frames, "frames to trace; the last is written")->check(CLI::Range(1u, 100000u))
      ->capture_default_str();
  app.add_option("--out", o.out, "PNG to write")->capture_default_str();
  app.add_option("--device", device, "cpu (lavapipe), gpu or auto (PROCEDURAY_DEVICE overrides auto)")
      ->check(CLI::IsMember({"cpu", "gpu", "auto"}))->capture_default_str();
  app.add_option("--cache", o.cache, "pipeline cache file (default: one per device in $XDG_CACHE_HOME/proceduray or ~/.cache/proceduray)");
  app.add_flag("--validation", o.validation, "enable the Khronos validation layer");
  if (extra) extra(app);
  try {
    app.parse(argc, argv);
    unsigned w = 0, h = 0;
    char extra_char = 0;
    if (std::sscanf(size.c_str(), "%ux%u%c", &w, &h, &extra_char) != 2 || w == 0 || h == 0) {
      throw std::invalid_argument("--size '" + size + "' is not WxH with positive numbers, e.g. 1024x768");
    }
    o.width = w;
    o.height = h;
    o.device = device == "cpu"   ? proceduray::vk::DevicePreference::cpu
               : device == "gpu" ? proceduray::vk::DevicePreference::gpu
                                 : proceduray::vk::DevicePreference::automatic;
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    o.exit = 0;
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s: %s\nrun with --help for the options\n", program, e.what());
    o.exit = 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "%s: %s\nrun with --help for the options\n", program, e.what());
    o.exit = 2;
  }
  return o;
}

}  // namespace examples
