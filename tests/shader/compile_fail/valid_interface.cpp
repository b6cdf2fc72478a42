// Control: the harness's flags compile a correct interface (so failures below are the intended ones).
// expect-success
#include <proceduray/shader/categories.hpp>
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct Hit {
  glm::vec3 normal;
  float t;
};
PROCEDURAY_STRUCT(Hit, std430, normal, t);
using Interface = proceduray::ShaderInterface<proceduray::Payload<Hit>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<Hit>, proceduray::Attributes<Hit>>;
static_assert(Interface::max_attribute_size == 16);
}  // namespace demo
