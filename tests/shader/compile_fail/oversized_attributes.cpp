// Hit attributes of 36 bytes exceed the 32 bytes Vulkan guarantees.
// expect: static assertion failed: Attributes: a hit attribute type is larger than 32 bytes
// expect: CategoryMember<proceduray::CategoryKind::attributes, demo::BigHit>
#include <proceduray/shader/categories.hpp>
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct BigHit {
  glm::vec4 a;
  glm::vec4 b;
  float c;
};
PROCEDURAY_STRUCT(BigHit, scalar, a, b, c);
using Attribs = proceduray::Attributes<BigHit>;
Attribs attribs;
}  // namespace demo
