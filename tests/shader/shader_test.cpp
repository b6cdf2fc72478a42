// Tests for proceduray/shader/shader.hpp: the umbrella alone is enough for the whole workflow.
#include <proceduray/shader/shader.hpp>

#include <doctest/doctest.h>

namespace umbrella_test {
struct Probe {
  glm::vec3 normal;
  float t;
};
PROCEDURAY_STRUCT(Probe, scalar, normal, t);
using Interface = proceduray::ShaderInterface<proceduray::Payload<Probe>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<>, proceduray::Attributes<Probe>>;
}  // namespace umbrella_test

TEST_CASE("the umbrella header declares a whole interface") {
  const std::string glsl = proceduray::glsl_declarations(umbrella_test::Interface::types);
  CHECK(glsl.find("struct Probe {\n    vec3 normal;\n    float t;\n};\n") != std::string::npos);
  static_assert(umbrella_test::Interface::max_attribute_size == 16);
  CHECK(proceduray::matches_host(proceduray::type_ops<umbrella_test::Probe>, proceduray::LayoutRule::std430));
}
