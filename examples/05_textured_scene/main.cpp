// Meshes that shade and textures that sample (issue 17): a tiled ground from a PNG, a smooth torus
// from an OBJ file, a mirror sphere, an environment map for the sky and its reflections, and
// beads that appear and disappear, one each frame. Prints timings and writes the last frame.
#include "../common/run.hpp"
#include "textured_scene.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  const examples::Options o = examples::parse(argc, argv, "05_textured_scene", {.width = 960, .height = 540});
  if (o.exit) return *o.exit;
  try {
    proceduray::check_writable(o.out);
    proceduray::vk::Context ctx({.device = o.device, .validation = o.validation});
    textured::TexturedScene scene;
    proceduray::vk::Renderer renderer(ctx, scene, examples::renderer_options(o, scene.renderer_options(o.cache)));
    textured::set_textures(renderer);
    renderer.set(textured::constants_slot, textured::default_constants(o.width, o.height));
    examples::print_build(ctx, renderer);
    textured::Beads beads;
    const examples::Run run = examples::run_frames(renderer, o, [&](std::uint32_t f) { beads.step(renderer, scene.beads(), f); });
    examples::print_run(run, o);
    std::printf("beads in the last frame: %zu (a TLAS build each frame)\n", beads.slots().size());
    examples::write_last(run, o);
    return ctx.validation_messages().empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "05_textured_scene: %s\n", e.what());
    return 1;
  }
}
