#include "tests/docs/vk/vk_names.hpp"
#include <proceduray/vk/field_knobs.hpp>
using namespace doc_vk;

// @declarations
void usage(const proceduray::Plan& plan, proceduray::vk::Bindings& bindings, const proceduray::Camera& camera,
           proceduray::GeometryId gyroid, const proceduray::MarchKnobs& knobs) {
  // @statements
}
