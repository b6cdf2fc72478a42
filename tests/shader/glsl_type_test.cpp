// Tests for proceduray/shader/glsl_type.hpp: the GLSL view of each supported C++ member type.
#include <proceduray/shader/glsl_type.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <string>

using proceduray::TypeKind;
using proceduray::type_ops;

namespace glsl_type_test {
struct NotRegistered {
  float x;
};
}  // namespace glsl_type_test

TEST_CASE("scalars map to their GLSL names") {
  static_assert(type_ops<float>.glsl_name == "float");
  static_assert(type_ops<std::int32_t>.glsl_name == "int");
  static_assert(type_ops<std::uint32_t>.glsl_name == "uint");
  static_assert(type_ops<double>.glsl_name == "double");
  static_assert(type_ops<std::uint64_t>.glsl_name == "uint64_t");
  static_assert(type_ops<double>.component_size == 8);
  static_assert(type_ops<float>.kind == TypeKind::scalar);
}

TEST_CASE("glm vectors and matrices map to their GLSL names") {
  static_assert(type_ops<glm::vec2>.glsl_name == "vec2");
  static_assert(type_ops<glm::ivec3>.glsl_name == "ivec3");
  static_assert(type_ops<glm::uvec4>.glsl_name == "uvec4");
  static_assert(type_ops<glm::dvec3>.glsl_name == "dvec3");
  static_assert(type_ops<glm::mat4>.glsl_name == "mat4");
  static_assert(type_ops<glm::mat3x4>.glsl_name == "mat3x4");
  static_assert(type_ops<glm::mat4x3>.glsl_name == "mat4x3");
  static_assert(type_ops<glm::mat4x3>.columns == 4);
  static_assert(type_ops<glm::mat4x3>.rows == 3);
  static_assert(type_ops<glm::vec3>.kind == TypeKind::vector);
  static_assert(type_ops<glm::mat4>.kind == TypeKind::matrix);
}

TEST_CASE("arrays and addresses describe their element") {
  static_assert(type_ops<float[3]>.kind == TypeKind::array);
  static_assert(type_ops<float[3]>.count == 3);
  static_assert(type_ops<float[3]>.element == &type_ops<float>);
  static_assert(type_ops<glm::vec2[2][5]>.element->count == 5);
  static_assert(type_ops<proceduray::DeviceAddress<float>>.kind == TypeKind::address);
  CHECK(type_ops<proceduray::DeviceAddress<float>>.pointee() == &type_ops<float>);
}

TEST_CASE("types without a GLSL equivalent are reported unsupported") {
  static_assert(type_ops<bool>.kind == TypeKind::unsupported);
  static_assert(type_ops<float*>.kind == TypeKind::unsupported);
  static_assert(type_ops<std::int64_t>.kind == TypeKind::unsupported);
  static_assert(type_ops<glm::dmat4>.kind == TypeKind::unsupported);
  static_assert(type_ops<glsl_type_test::NotRegistered>.kind == TypeKind::unregistered_struct);
  CHECK_FALSE(proceduray::GlslMember<bool>);
  CHECK_FALSE(proceduray::GlslMember<std::string>);
  CHECK_FALSE(proceduray::GlslMember<bool[2]>);
  CHECK_FALSE(proceduray::GlslMember<proceduray::DeviceAddress<bool>>);
  CHECK_FALSE(proceduray::GlslMember<proceduray::DeviceAddress<float[2]>>);
  CHECK(proceduray::GlslMember<glm::mat3x4[2]>);
  CHECK(proceduray::GlslMember<proceduray::DeviceAddress<glm::vec3>>);
  CHECK_FALSE(proceduray::RegisteredIfStruct<glsl_type_test::NotRegistered[2]>);
  CHECK_FALSE(proceduray::RegisteredIfStruct<proceduray::DeviceAddress<glsl_type_test::NotRegistered>>);
  CHECK(proceduray::RegisteredIfStruct<bool>);
}

TEST_CASE("type names come from the compiler") {
  CHECK(type_ops<glsl_type_test::NotRegistered>.cpp_name() == "glsl_type_test::NotRegistered");
  CHECK(type_ops<float>.cpp_name() == "float");
}
