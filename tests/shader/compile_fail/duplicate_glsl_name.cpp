// Two different types named Twin in one interface would clash in GLSL.
// expect: static assertion failed: ShaderInterface: two different types have the same GLSL struct name
// expect: NameClash<a::Twin, b::Twin, true>
#include <proceduray/shader/categories.hpp>
#include <proceduray/shader/field_list.hpp>

namespace a {
struct Twin {
  float x;
};
PROCEDURAY_STRUCT(Twin, scalar, x);
}  // namespace a
namespace b {
struct Twin {
  std::uint32_t y;
};
PROCEDURAY_STRUCT(Twin, scalar, y);
}  // namespace b
using Interface = proceduray::ShaderInterface<proceduray::Payload<a::Twin>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<b::Twin>, proceduray::Attributes<>>;
constexpr auto size = Interface::max_payload_size;
