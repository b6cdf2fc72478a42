// Tests for proceduray/shader/define_struct.hpp: a struct declared and registered in one go is the
// same struct, with the same field list and GLSL, as one written out and registered with PROCEDURAY_STRUCT.
#include <proceduray/shader/define_struct.hpp>
#include <proceduray/shader/glsl_codegen.hpp>

#include "test_types.hpp"

#include <doctest/doctest.h>

#include <cstddef>
#include <string>
#include <type_traits>

namespace define_struct_test {

using shader_test::Light;
using shader_test::Sphere;

// The same members as shader_test::Material430 (std430: matrices, nested array, C array, address).
PROCEDURAY_DEFINE_STRUCT(Defined430, std430,
    (glm::mat4, transform),
    (glm::mat3x4, basis),
    (Light[2], lights),                            ///< arrays of registered structs, as written in C++
    (glm::vec4, tint),
    (std::uint32_t[4], flags),
    (proceduray::DeviceAddress<Light>, more),
    (std::uint64_t, count));

// The same members as shader_test::ScalarMix (scalar: a double, a nested 2D array).
PROCEDURAY_DEFINE_STRUCT(DefinedScalar, scalar,
    (double, d),
    (glm::vec3, v),
    (float, f),
    (std::uint64_t, u),
    (glm::ivec2, iv),
    (proceduray::DeviceAddress<Sphere>, spheres),
    (Sphere[2], nested),
    (glm::uvec3[2][2], grid));

PROCEDURAY_DEFINE_STRUCT(Single, scalar, (std::uint32_t, occluded));

// A defined struct nests like any registered one.
PROCEDURAY_DEFINE_STRUCT(Outer, scalar, (Single, inner), (float, weight));

PROCEDURAY_DEFINE_STRUCT(Widest, std430,
    (float, m00), (float, m01), (float, m02), (float, m03), (float, m04), (float, m05), (float, m06), (float, m07),
    (float, m08), (float, m09), (float, m10), (float, m11), (float, m12), (float, m13), (float, m14), (float, m15),
    (float, m16), (float, m17), (float, m18), (float, m19), (float, m20), (float, m21), (float, m22), (float, m23),
    (float, m24), (float, m25), (float, m26), (float, m27), (float, m28), (float, m29), (float, m30), (float, m31));

/// The field list of `a` and `b` agree: names, offsets, sizes, member types, rule and size.
void check_same_fields(const proceduray::TypeOps& a, const proceduray::TypeOps& b) {
  REQUIRE(a.field_count == b.field_count);
  CHECK(a.rule == b.rule);
  CHECK(a.cpp_size == b.cpp_size);
  for (std::size_t i = 0; i < a.field_count; ++i) {
    CAPTURE(i);
    CHECK(a.fields[i].name == b.fields[i].name);
    CHECK(a.fields[i].offset == b.fields[i].offset);
    CHECK(a.fields[i].size == b.fields[i].size);
    CHECK(a.fields[i].type == b.fields[i].type);
  }
}

/// The GLSL struct declaration of T alone.
template <class T>
std::string glsl_of() {
  const proceduray::TypeOps* roots[] = {&proceduray::type_ops<T>};
  return proceduray::glsl_declarations(roots, false);
}

/// `text` with every `from` replaced by `to`.
std::string renamed(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

}  // namespace define_struct_test

using namespace define_struct_test;
using proceduray::type_ops;

TEST_CASE("a defined struct has the field list of the same struct registered by hand") {
  check_same_fields(type_ops<Defined430>, type_ops<shader_test::Material430>);
  check_same_fields(type_ops<DefinedScalar>, type_ops<shader_test::ScalarMix>);
  static_assert(type_ops<Defined430>.glsl_name == "Defined430");
  static_assert(type_ops<Defined430>.fields[2].type->element == &type_ops<Light>);
  static_assert(sizeof(Defined430) == sizeof(shader_test::Material430));
  static_assert(sizeof(DefinedScalar) == sizeof(shader_test::ScalarMix));
}

TEST_CASE("a defined struct generates the GLSL of the same struct registered by hand") {
  const std::string by_hand = glsl_of<shader_test::Material430>();
  REQUIRE(by_hand.find("struct Material430 {") != std::string::npos);
  CHECK(glsl_of<Defined430>() == renamed(by_hand, "Material430", "Defined430"));
  CHECK(glsl_of<DefinedScalar>() == renamed(glsl_of<shader_test::ScalarMix>(), "ScalarMix", "DefinedScalar"));
  CHECK(glsl_of<Outer>().find("struct Single {\n    uint occluded;\n};") != std::string::npos);
  CHECK(glsl_of<Outer>().find("struct Outer {\n    Single inner;\n    float weight;\n};") != std::string::npos);
}

TEST_CASE("a defined struct is a plain aggregate with its members in order") {
  static_assert(std::is_aggregate_v<Outer>);
  static_assert(std::is_trivially_copyable_v<DefinedScalar> && std::is_standard_layout_v<DefinedScalar>);
  static_assert(std::is_same_v<decltype(Defined430::flags), std::uint32_t[4]>);
  static_assert(std::is_same_v<decltype(DefinedScalar::grid), glm::uvec3[2][2]>);
  constexpr Outer o{{7u}, 0.5f};
  static_assert(o.inner.occluded == 7u && o.weight == 0.5f);
  static_assert(offsetof(Outer, weight) == 4);
  static_assert(type_ops<Outer>.fields[1].offset == 4);
}

TEST_CASE("a defined struct takes 32 members") {
  static_assert(type_ops<Widest>.field_count == 32);
  static_assert(type_ops<Widest>.fields[31].name == "m31");
  static_assert(type_ops<Widest>.fields[31].offset == 31 * sizeof(float));
  static_assert(sizeof(Widest) == 32 * sizeof(float));
}
