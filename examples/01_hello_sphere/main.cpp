// Renders two procedural spheres to a PNG and prints its path.
//
//   01_hello_sphere [--out PATH] [--size WxH] [--device cpu|gpu|auto] [--validation]
#include "../common/cli.hpp"
#include "hello_sphere.hpp"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <vector>

int main(int argc, char** argv) {
  const examples::Options o = examples::parse(argc, argv, "01_hello_sphere", {.width = 640, .height = 360});
  if (o.exit) return *o.exit;
  try {
    proceduray::check_writable(o.out);  // fail before the expensive part
    proceduray::vk::Context ctx({.device = o.device, .validation = o.validation});
    std::fprintf(stderr, "device: %s\n", ctx.name().c_str());
    hello_sphere::HelloSphere scene(ctx);
    std::vector<std::uint8_t> rgba;
    for (std::uint32_t f = 0; f < o.frames; ++f) rgba = scene.render(o.width, o.height);
    proceduray::write_png(o.out, o.width, o.height, rgba);
    std::printf("%s\n", std::filesystem::absolute(o.out).string().c_str());
    return ctx.validation_messages().empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "01_hello_sphere: %s\n", e.what());
    return 1;
  }
}
