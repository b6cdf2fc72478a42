// Command-line options shared by the examples (size, frames, output, device, cache,
// validation), parsed by CLI11 (Debian: libcli11-dev); an example adds its own options.
//
//   examples::Options o = examples::parse(argc, argv, "02_paper_scene", {.width = 1024, .height = 768});
//   if (o.exit) return *o.exit;   // --help printed, or a bad option reported (status 2)
//   bool bench = false;            // an example's own option (that file includes <CLI/CLI.hpp>):
//   o = examples::parse(argc, argv, "03_d3d12_scene", {}, [&](CLI::App& app) { app.add_flag("--bench", bench); });
#pragma once

#include "paths.hpp"

#include <proceduray/vk/context.hpp>
#include <proceduray/vk/scene_pipeline.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>

namespace CLI {
class App;
}  // namespace CLI

namespace examples {

struct Options {
  std::uint32_t width = 640;
  std::uint32_t height = 360;
  std::uint32_t frames = 1;
  std::filesystem::path out;  ///< default: <program>.png
  proceduray::vk::DevicePreference device = proceduray::vk::DevicePreference::automatic;
  bool validation = false;
  std::filesystem::path cache;  ///< pipeline cache file; default: the cache folder's
  bool general = false;         ///< fields read their knobs per ray (RendererOptions::specialize_fields off)
  std::optional<int> exit;      ///< set when the program should stop with this code
};

/// Parses the shared options over `defaults`, and an example's own through `extra`. A bad
/// option prints "<program>: <what and the fix>" and sets exit to 2; --help sets it to 0.
/// Compiled once in cli.cpp: CLI11 is header-only and costs seconds in every file that includes it,
/// so only the examples that add options of their own include <CLI/CLI.hpp>.
Options parse(int argc, char** argv, const char* program, Options defaults,
              const std::function<void(CLI::App&)>& extra = {});

/// `options` with what the command line asks of the renderer (--general).
inline proceduray::vk::RendererOptions renderer_options(const Options& o, proceduray::vk::RendererOptions options) {
  options.specialize_fields = !o.general;
  return options;
}

}  // namespace examples
