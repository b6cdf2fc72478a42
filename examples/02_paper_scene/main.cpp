// The report's figure 3: a plane, two CSG Pac-men, a Julia set cut by a plane and a
// Mandelbulb, with shadows and reflections; animated over --frames. Prints timings and the SBT.
// --origin X,Y,Z places the scene far from (0, 0, 0), drawn relative to a WorldOrigin at the
// camera (world.hpp); --raw-floats drops the re-origin, to see the error it removes.
#include "../common/run.hpp"
#include "paper_scene.hpp"
#include "world_options.hpp"

int main(int argc, char** argv) {
  paper::WorldOptions where;
  paper::World world;
  const auto options = [&](CLI::App& app) { paper::add_world_options(app, where); };
  const auto scene = [&] {
    world = where.world();
    return paper::PaperScene({}, paper::Tracing::recursive, paper::max_depth_limit, world);
  };
  const auto constants = [&](const examples::Options& o, std::uint32_t frame) {
    paper::SceneConstants c = paper::default_constants(o.width, o.height, 0.1f * static_cast<float>(frame));  // 0.1 s per frame
    world.place(c);
    return c;
  };
  return examples::run_scene(argc, argv, "02_paper_scene", {.width = 1024, .height = 768}, paper::constants_slot, constants,
                             scene, options);
}
