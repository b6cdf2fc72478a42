// Tests for proceduray/shader/glsl_codegen.hpp: golden text, declarations, name clashes.
#include <proceduray/shader/glsl_codegen.hpp>

#include "test_types.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace shader_test;
using proceduray::type_ops;

namespace {

std::string read_golden(const char* name) {
  const std::filesystem::path path = std::filesystem::path(__FILE__).parent_path() / "golden" / name;
  std::ifstream in(path);
  REQUIRE_MESSAGE(in.good(), "cannot read ", path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

namespace clash_a {
struct Twin {
  float x;
};
PROCEDURAY_STRUCT(Twin, scalar, x);
}  // namespace clash_a
namespace clash_b {
struct Twin {
  std::uint32_t y;
};
PROCEDURAY_STRUCT(Twin, scalar, y);
struct Holder {
  clash_a::Twin a;
  Twin b;
};
PROCEDURAY_STRUCT(Holder, scalar, a, b);
struct FloatRef {
  float f;
};
PROCEDURAY_STRUCT(FloatRef, scalar, f);
}  // namespace clash_b

TEST_CASE("interface declarations match the golden text") {
  CHECK(proceduray::glsl_declarations(Interface::types) == read_golden("interface.glsl"));
}

TEST_CASE("nested structs arrays addresses and matrices match the golden text") {
  const proceduray::TypeOps* roots[] = {&type_ops<ScalarMix>, &type_ops<Material430>, &type_ops<ListNode>,
                                        &type_ops<Basis>, &type_ops<Outer140>};
  CHECK(proceduray::glsl_declarations(roots, false) == read_golden("representative.glsl"));
}

TEST_CASE("structs come after the structs they contain") {
  const proceduray::TypeOps* roots[] = {&type_ops<Outer140>};
  const std::string glsl = proceduray::glsl_declarations(roots, false);
  REQUIRE(glsl.find("struct Inner140 {") != std::string::npos);
  CHECK(glsl.find("struct Inner140 {") < glsl.find("struct Outer140 {"));
  CHECK(glsl.find("#extension") == std::string::npos);  // std140 only: no extension needed
}

TEST_CASE("generation is deterministic") {
  CHECK(proceduray::glsl_declarations(Interface::types) == proceduray::glsl_declarations(Interface::types));
}

TEST_CASE("payload declarations carry the payload location") {
  CHECK(proceduray::glsl_ray_payload(Interface::payload_location<RadiancePayload>(), type_ops<RadiancePayload>, "radiance") ==
        "layout(location = 0) rayPayloadEXT RadiancePayload radiance;\n");
  CHECK(proceduray::glsl_ray_payload(Interface::payload_location<ShadowPayload>(), type_ops<ShadowPayload>, "shadow") ==
        "layout(location = 1) rayPayloadEXT ShadowPayload shadow;\n");
  CHECK(proceduray::glsl_ray_payload(Interface::payload_location<ShadowPayload>(), type_ops<ShadowPayload>, "shadow", true) ==
        "layout(location = 1) rayPayloadInEXT ShadowPayload shadow;\n");
}

TEST_CASE("hit attributes and shader records are declared from their types") {
  CHECK(proceduray::glsl_hit_attribute(type_ops<SphereHit>, "hit") == "hitAttributeEXT SphereHit hit;\n");
  CHECK(proceduray::glsl_root_arguments(type_ops<SphereRecord>, "arguments") ==
        "layout(shaderRecordEXT, scalar) buffer SphereRecordRootArguments {\n"
        "    SphereRef spheres;\n"
        "    vec4 albedo;\n"
        "    uint count;\n"
        "    uint pad;\n"
        "} arguments;\n");
  CHECK(proceduray::glsl_root_arguments(type_ops<Material430>, "material").starts_with(
      "layout(shaderRecordEXT, std430) buffer Material430RootArguments {\n    mat4 transform;\n"));
}

TEST_CASE("push constants are declared from their type and rule") {
  CHECK(proceduray::glsl_push_constant<Inner140>("inner") ==
        "layout(push_constant, std140) uniform Inner140PushConstants {\n    vec4 a;\n} inner;\n");
}

TEST_CASE("uniform blocks are declared from their type rule set and binding") {
  CHECK(proceduray::glsl_uniform<Inner140>(0, 3, "inner") ==
        "layout(set = 0, binding = 3, std140) uniform Inner140Uniform {\n    vec4 a;\n} inner;\n");
  CHECK(proceduray::glsl_uniform<Sphere>(1, 2, "sphere") ==
        "layout(set = 1, binding = 2, scalar) uniform SphereUniform {\n    vec3 center;\n    float radius;\n} sphere;\n");
}

TEST_CASE("glsl_type_name names references after their target") {
  CHECK(proceduray::glsl_type_name(type_ops<proceduray::DeviceAddress<Sphere>>) == "SphereRef");
  CHECK(proceduray::glsl_type_name(type_ops<proceduray::DeviceAddress<glm::vec3>>) == "Vec3Ref");
  CHECK(proceduray::glsl_type_name(type_ops<proceduray::DeviceAddress<std::uint64_t>>) == "Uint64Ref");
  CHECK(proceduray::glsl_type_name(type_ops<glm::uvec3[2][2]>) == "uvec3");
}

TEST_CASE("two types with one GLSL name throw naming both") {
  const proceduray::TypeOps* roots[] = {&type_ops<clash_b::Holder>};
  CHECK_THROWS_WITH_AS(proceduray::glsl_declarations(roots, false),
                       "glsl_declarations: the GLSL name 'Twin' is used by both clash_a::Twin and clash_b::Twin; "
                       "rename one of the C++ types",
                       proceduray::GlslNameError);
}

TEST_CASE("a struct named like a generated reference type throws") {
  const proceduray::TypeOps* roots[] = {&type_ops<clash_b::FloatRef>, &type_ops<ListNode>};
  CHECK_THROWS_AS(proceduray::glsl_declarations(roots, false), proceduray::GlslNameError);
}

TEST_CASE("insert_after_version keeps version first and line numbers right") {
  const std::string out = proceduray::insert_after_version("#version 460\nvoid main() {}\n", "struct A { float x; };\n");
  CHECK(out == "#version 460\nstruct A { float x; };\n#line 2\nvoid main() {}\n");
  CHECK(proceduray::insert_after_version("void main() {}\n", "// g\n") == "// g\n#line 1\nvoid main() {}\n");
}

TEST_CASE("glsl_const writes host constants exactly") {
  CHECK(proceduray::glsl_const("flags", 6u) == "const uint flags = 6u;\n");
  CHECK(proceduray::glsl_const("half", 0.5f) == "const float half = 0.5;\n");
  CHECK(proceduray::glsl_const("one", 1.0f) == "const float one = 1.0;\n");
  CHECK(proceduray::glsl_const("tiny", 1e-4f) == "const float tiny = 1e-04;\n");
  CHECK(proceduray::glsl_const("box_min", glm::vec3(-1.5f, 0.0f, 2.25f)) ==
        "const vec3 box_min = vec3(-1.5, 0.0, 2.25);\n");
}
