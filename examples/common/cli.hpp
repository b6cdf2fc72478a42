// Command-line options shared by the examples: size, frames, output, device, validation.
//
//   examples::Options o = examples::parse(argc, argv, "02_paper_scene", {.width = 1024, .height = 768});
//   if (o.exit) return *o.exit;   // --help printed, or a bad option reported
#pragma once

#include <proceduray/vk/context.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
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
  std::filesystem::path cache;  ///< pipeline cache file; default none
  std::optional<int> exit;      ///< set when the program should stop with this code
};

/// Where an example's own files (shaders) are: $PROCEDURAY_EXAMPLES_DIR, else the source tree's.
inline std::filesystem::path examples_dir() {
  if (const char* env = std::getenv("PROCEDURAY_EXAMPLES_DIR"); env != nullptr && *env != '\0') return env;
#ifdef PROCEDURAY_EXAMPLES_DIR
  return PROCEDURAY_EXAMPLES_DIR;
#else
  return std::filesystem::current_path();
#endif
}

/// Where the build wrote a scene's GLSL declarations (`built`, a path compiled in); the
/// environment variable PROCEDURAY_GLSL_DIR overrides it, for binaries carried to another machine.
inline std::filesystem::path generated_glsl_dir(const char* built) {
  if (const char* env = std::getenv("PROCEDURAY_GLSL_DIR"); env != nullptr && *env != '\0') return env;
  return built;
}

inline Options parse(int argc, char** argv, const char* program, Options defaults) {
  Options o = defaults;
  if (o.out.empty()) o.out = std::string(program) + ".png";
  const std::string help = std::string("usage: ") + program +
                           " [--size WxH] [--frames N] [--out PATH] [--device cpu|gpu|auto] [--cache PATH] "
                           "[--validation]\n  --size WxH    image size (default " + std::to_string(o.width) + "x" +
                           std::to_string(o.height) + ")\n  --frames N    frames to trace; the last is written "
                           "(default " + std::to_string(o.frames) + ")\n  --out PATH    PNG to write (default " +
                           o.out.string() + ")\n  --device D    cpu (lavapipe), gpu or auto (default; "
                           "PROCEDURAY_DEVICE overrides auto)\n  --cache PATH  pipeline cache file (default none)\n"
                           "  --validation  enable the Khronos validation layer\n";
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
        return argv[++i];
      };
      if (arg == "--help" || arg == "-h") {
        std::fputs(help.c_str(), stdout);
        o.exit = 0;
        return o;
      } else if (arg == "--size") {
        const std::string v = value();
        unsigned w = 0, h = 0;
        char extra = 0;
        if (std::sscanf(v.c_str(), "%ux%u%c", &w, &h, &extra) != 2 || w == 0 || h == 0) {
          throw std::invalid_argument("--size '" + v + "' is not WxH with positive numbers, e.g. 1024x768");
        }
        o.width = w;
        o.height = h;
      } else if (arg == "--frames") {
        const std::string v = value();
        char* end = nullptr;
        const unsigned long n = std::strtoul(v.c_str(), &end, 10);
        if (v.empty() || *end != '\0' || n == 0 || n > 100000) {
          throw std::invalid_argument("--frames '" + v + "' is not a count from 1 to 100000");
        }
        o.frames = static_cast<std::uint32_t>(n);
      } else if (arg == "--out") {
        o.out = value();
      } else if (arg == "--cache") {
        o.cache = value();
      } else if (arg == "--device") {
        const std::string v = value();
        if (v == "cpu") o.device = proceduray::vk::DevicePreference::cpu;
        else if (v == "gpu") o.device = proceduray::vk::DevicePreference::gpu;
        else if (v == "auto") o.device = proceduray::vk::DevicePreference::automatic;
        else throw std::invalid_argument("--device '" + v + "' is not one of cpu, gpu, auto");
      } else if (arg == "--validation") {
        o.validation = true;
      } else {
        throw std::invalid_argument("unknown option '" + arg + "'");
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n%s", program, e.what(), help.c_str());
    o.exit = 2;
  }
  return o;
}

}  // namespace examples
