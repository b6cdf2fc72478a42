// Renders two procedural spheres to a PNG and prints its path.
//
//   01_hello_sphere [--out PATH] [--size WxH] [--device cpu|gpu|auto] [--validation]
#include "hello_sphere.hpp"

#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>

namespace {

void usage(std::FILE* to) {
  std::fputs(
      "usage: 01_hello_sphere [--out PATH] [--size WxH] [--device cpu|gpu|auto] [--validation]\n"
      "  --out PATH     PNG to write (default: hello_sphere.png)\n"
      "  --size WxH     image size (default: 640x360)\n"
      "  --device D     cpu (lavapipe), gpu, or auto (default; PROCEDURAY_DEVICE overrides auto)\n"
      "  --validation   enable the Khronos validation layer\n",
      to);
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path out = "hello_sphere.png";
  std::uint32_t width = 640;
  std::uint32_t height = 360;
  proceduray::vk::ContextOptions options;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
        return argv[++i];
      };
      if (arg == "--help" || arg == "-h") {
        usage(stdout);
        return 0;
      } else if (arg == "--out") {
        out = value();
      } else if (arg == "--size") {
        const std::string v = value();
        unsigned w = 0, h = 0;
        char extra = 0;
        if (std::sscanf(v.c_str(), "%ux%u%c", &w, &h, &extra) != 2 || w == 0 || h == 0) {
          throw std::invalid_argument("--size '" + v + "' is not WxH with positive numbers, e.g. 640x360");
        }
        width = w;
        height = h;
      } else if (arg == "--device") {
        const std::string v = value();
        if (v == "cpu") options.device = proceduray::vk::DevicePreference::cpu;
        else if (v == "gpu") options.device = proceduray::vk::DevicePreference::gpu;
        else if (v == "auto") options.device = proceduray::vk::DevicePreference::automatic;
        else throw std::invalid_argument("--device '" + v + "' is not one of cpu, gpu, auto");
      } else if (arg == "--validation") {
        options.validation = true;
      } else {
        throw std::invalid_argument("unknown option '" + arg + "'");
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "01_hello_sphere: %s\n", e.what());
    usage(stderr);
    return 2;
  }
  try {
    proceduray::check_writable(out);  // fail before the expensive part
    proceduray::vk::Context ctx(options);
    std::fprintf(stderr, "device: %s\n", ctx.name().c_str());
    hello_sphere::HelloSphere scene(ctx);
    const auto rgba = scene.render(width, height);
    proceduray::write_png(out, width, height, rgba);
    std::printf("%s\n", std::filesystem::absolute(out).string().c_str());
    if (!ctx.validation_messages().empty()) {
      std::fprintf(stderr, "01_hello_sphere: the validation layer reported %zu messages\n",
                   ctx.validation_messages().size());
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "01_hello_sphere: %s\n", e.what());
    return 1;
  }
  return 0;
}
