// The shared options' parser (see cli.hpp), compiled once into the examples' common library.
#include "cli.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <stdexcept>
#include <string>

namespace examples {

Options parse(int argc, char** argv, const char* program, Options defaults, const std::function<void(CLI::App&)>& extra) {
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
  app.add_flag("--general", o.general, "the general pipeline: distance fields read their knobs per ray instead of "
                                        "having them compiled in (slower; what a sweep uses)");
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
