// A payload type is not root arguments: using it as RootArguments does not compile.
// expect: static assertion failed: ShaderInterface::root_arguments: the type is not in this interface's RootArguments category
// expect-gcc: [with T = demo::Radiance
// expect-clang: 'RootArguments<demo::Record>::contains<demo::Radiance>'
#include <proceduray/shader/categories.hpp>
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct Radiance {
  glm::vec3 color;
  float alpha;
};
PROCEDURAY_STRUCT(Radiance, scalar, color, alpha);
struct Record {
  glm::vec4 albedo;
};
PROCEDURAY_STRUCT(Record, scalar, albedo);
using Interface = proceduray::ShaderInterface<proceduray::Payload<Radiance>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<Record>, proceduray::Attributes<>>;
auto bytes = Interface::root_arguments(Radiance{});
}  // namespace demo
