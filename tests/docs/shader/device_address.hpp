#include <proceduray/shader/field_list.hpp>
#include "tests/docs/doc_types.hpp"
using doc_types::Sphere;
// @declarations
void usage(std::uint64_t buffer_address) {
  SphereRecord record{};
  // @statements
}
