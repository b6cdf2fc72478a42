// Tests for proceduray/shader/field_list.hpp: what PROCEDURAY_STRUCT records about a struct.
#include <proceduray/shader/field_list.hpp>

#include "test_types.hpp"

#include <doctest/doctest.h>

#include <cstddef>
#include <string_view>

using namespace shader_test;
using proceduray::type_ops;

namespace field_list_test {
struct Wide {
  float m00, m01, m02, m03, m04, m05, m06, m07, m08, m09, m10, m11, m12, m13, m14, m15;
  float m16, m17, m18, m19, m20, m21, m22, m23, m24, m25, m26, m27, m28, m29, m30, m31;
};
PROCEDURAY_STRUCT(Wide, std430, m00, m01, m02, m03, m04, m05, m06, m07, m08, m09, m10, m11, m12, m13, m14, m15,
                  m16, m17, m18, m19, m20, m21, m22, m23, m24, m25, m26, m27, m28, m29, m30, m31);
}  // namespace field_list_test

TEST_CASE("a registered struct lists its members in order with C++ offsets") {
  const proceduray::TypeOps& t = type_ops<Light>;
  REQUIRE(t.field_count == 5);
  CHECK(t.kind == proceduray::TypeKind::structure);
  CHECK(t.glsl_name == "Light");
  CHECK(t.rule == proceduray::LayoutRule::std430);
  CHECK(t.fields[0].name == "position");
  CHECK(t.fields[3].name == "ids");
  CHECK(t.fields[3].offset == offsetof(Light, ids));
  CHECK(t.fields[3].size == sizeof(glm::uvec2));
  CHECK(t.fields[3].type == &type_ops<glm::uvec2>);
  CHECK(t.cpp_size == sizeof(Light));
}

TEST_CASE("the field list is usable at compile time") {
  static_assert(type_ops<ScalarMix>.field_count == 8);
  static_assert(type_ops<ScalarMix>.fields[6].type->kind == proceduray::TypeKind::array);
  static_assert(type_ops<ScalarMix>.fields[6].type->element == &type_ops<Sphere>);
  static_assert(proceduray::FieldsOf<Sphere>::rule == proceduray::LayoutRule::scalar);
  CHECK(proceduray::FieldsOf<Sphere>::glsl_name == "Sphere");
}

TEST_CASE("a struct may point to its own type") {
  const proceduray::TypeOps& next = *type_ops<ListNode>.fields[1].type;
  REQUIRE(next.kind == proceduray::TypeKind::address);
  CHECK(next.pointee() == &type_ops<ListNode>);
}

TEST_CASE("32 members are supported") {
  static_assert(type_ops<field_list_test::Wide>.field_count == 32);
  static_assert(type_ops<field_list_test::Wide>.fields[31].name == "m31");
  static_assert(type_ops<field_list_test::Wide>.fields[31].offset == 124);
}

TEST_CASE("registration is visible through the RegisteredStruct concept") {
  CHECK(proceduray::RegisteredStruct<Sphere>);
  CHECK_FALSE(proceduray::RegisteredStruct<glm::vec3>);
  CHECK_FALSE(proceduray::RegisteredStruct<proceduray::Extent>);
}
