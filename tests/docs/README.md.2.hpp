// README.md's second ```cpp block: calibrating the field (examples/06_your_field/main.cpp).
#include "tests/docs/field_names.hpp"
using namespace doc_field;
// @declarations
void usage(const pr::vk::Context& ctx, const pr::DistanceField& field, std::uint32_t width, std::uint32_t height) {
  // @statements
}
