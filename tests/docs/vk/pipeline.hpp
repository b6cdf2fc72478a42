#include "tests/docs/vk/vk_names.hpp"
using namespace doc_vk;

// @declarations
void usage(const proceduray::vk::Context& ctx, const proceduray::vk::DescriptorSet& set, const std::string& rgen_glsl, const std::vector<std::uint32_t>& miss_spirv,
           const std::vector<std::uint32_t>& hit_spirv, const std::vector<std::uint32_t>& isec_spirv) {
  // @statements
}
