// The report's figure 3: a plane, two CSG Pac-men, a Julia set cut by a plane and a
// Mandelbulb, with shadows and reflections; animated over --frames. Prints timings and the SBT.
#include "../common/run.hpp"
#include "paper_scene.hpp"

int main(int argc, char** argv) {
  const auto constants = [](const examples::Options& o, std::uint32_t frame) {
    return paper::default_constants(o.width, o.height, 0.1f * static_cast<float>(frame));  // 0.1 s per frame
  };
  return examples::run_scene<paper::PaperScene>(argc, argv, "02_paper_scene", {.width = 1024, .height = 768},
                                                paper::constants_slot, constants);
}
