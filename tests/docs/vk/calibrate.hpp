#include "tests/docs/vk/vk_names.hpp"
#include <proceduray/vk/calibrate.hpp>
#include <proceduray/scene/scene.hpp>
#include "tests/docs/doc_types.hpp"
#include <cstdio>
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, const proceduray::DistanceField& gyroid, double (*cpu)(glm::dvec3),
           const proceduray::vk::MeasureView& view, proceduray::Scene<doc_types::DocInterface>& scene) {
  // @statements
}
