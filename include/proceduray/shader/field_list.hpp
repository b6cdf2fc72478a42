// Field lists: register a C++ struct once, get its GLSL name, members, offsets and layout checks.
//
//   struct Sphere { glm::vec3 center; float radius; };
//   PROCEDURAY_STRUCT(Sphere, scalar, center, radius);      // at namespace scope, in Sphere's namespace
//
//   struct Material { glm::vec4 albedo; Sphere bounds; proceduray::DeviceAddress<Sphere> spheres; };
//   PROCEDURAY_STRUCT(Material, scalar, albedo, bounds, spheres);   // nested types registered first
//
//   proceduray::type_ops<Sphere>.fields[1].name == "radius";   // members in declaration order
//
// The macro names the struct, its layout rule (scalar, std430 or std140) and every member, in
// declaration order (at most 32). It static_asserts, with messages naming struct, member and rule:
// every member type has a GLSL equivalent, nested structs are registered, no name is a GLSL reserved
// word, each C++ offset (and the layout inside each member) equals the rule's, and sizeof equals the
// rule's struct size. The GLSL struct name is the C++ name. PROCEDURAY_DEFINE_STRUCT
// (define_struct.hpp) declares the struct and registers it in one go, naming each member once.
#pragma once

#include <proceduray/shader/glsl_keywords.hpp>
#include <proceduray/shader/glsl_type.hpp>
#include <proceduray/shader/layout.hpp>

#include <cstddef>
#include <string_view>
#include <type_traits>

namespace proceduray::detail {

template <class T>
concept PlainStruct = std::is_class_v<T> && std::is_standard_layout_v<T> && std::is_trivially_copyable_v<T>;

constexpr bool is_checkable(const TypeOps& t) {
  switch (t.kind) {
    case TypeKind::unsupported:
    case TypeKind::unregistered_struct: return false;
    case TypeKind::array: return is_checkable(*t.element);
    default: return true;
  }
}

/// Member `index` matches its struct's rule; vacuously true when the member type is already reported as bad.
constexpr bool field_ok(const TypeOps& s, std::size_t index) {
  for (std::size_t i = 0; i <= index; ++i) {
    if (!is_checkable(*s.fields[i].type)) return true;
  }
  return field_matches(s, index, s.rule);
}

/// The struct's size matches its rule; vacuously true when a member type is already reported as bad.
constexpr bool size_ok(const TypeOps& s) {
  for (std::size_t i = 0; i < s.field_count; ++i) {
    if (!is_checkable(*s.fields[i].type)) return true;
  }
  return extent_of(s, s.rule).size == s.cpp_size;
}

}  // namespace proceduray::detail

#define PROCEDURAY_DETAIL_CAT_(a, b) a##b
#define PROCEDURAY_DETAIL_CAT(a, b) PROCEDURAY_DETAIL_CAT_(a, b)
#define PROCEDURAY_DETAIL_COUNT_(_1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24, _25, _26, _27, _28, _29, _30, _31, _32, n, ...) n
#define PROCEDURAY_DETAIL_COUNT(...) PROCEDURAY_DETAIL_COUNT_(__VA_ARGS__, 32, 31, 30, 29, 28, 27, 26, 25, 24, 23, 22, 21, 20, 19, 18, 17, 16, 15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0)
#define PROCEDURAY_DETAIL_FE_1(F, T, R, I, m) F(T, R, I, m)
#define PROCEDURAY_DETAIL_FE_2(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_1(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_3(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_2(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_4(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_3(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_5(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_4(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_6(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_5(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_7(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_6(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_8(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_7(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_9(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_8(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_10(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_9(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_11(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_10(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_12(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_11(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_13(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_12(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_14(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_13(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_15(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_14(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_16(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_15(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_17(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_16(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_18(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_17(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_19(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_18(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_20(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_19(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_21(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_20(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_22(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_21(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_23(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_22(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_24(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_23(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_25(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_24(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_26(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_25(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_27(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_26(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_28(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_27(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_29(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_28(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_30(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_29(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_31(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_30(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FE_32(F, T, R, I, m, ...) F(T, R, I, m) PROCEDURAY_DETAIL_FE_31(F, T, R, I + 1, __VA_ARGS__)
#define PROCEDURAY_DETAIL_FOR_EACH(F, T, R, ...) \
  PROCEDURAY_DETAIL_CAT(PROCEDURAY_DETAIL_FE_, PROCEDURAY_DETAIL_COUNT(__VA_ARGS__))(F, T, R, 0, __VA_ARGS__)

#define PROCEDURAY_DETAIL_FIELD(T, R, I, m) \
  ::proceduray::Field{#m, offsetof(T, m), sizeof(T::m), &::proceduray::type_ops<decltype(T::m)>},

#define PROCEDURAY_DETAIL_CHECK(T, R, I, m)                                                                     \
  static_assert(!::proceduray::is_glsl_reserved(#m),                                                          \
                #T "::" #m ": the member's name is a reserved GLSL word; rename the member");                  \
  static_assert(::proceduray::RegisteredIfStruct<decltype(T::m)>,                                              \
                #T "::" #m ": the member's struct type is not registered; add PROCEDURAY_STRUCT for it before " \
                #T);                                                                                           \
  static_assert(::proceduray::GlslMember<decltype(T::m)> || !::proceduray::RegisteredIfStruct<decltype(T::m)>, \
                #T "::" #m ": unsupported member type; use float, int32_t, uint32_t, double, uint64_t, a glm "   \
                "vector or float matrix, a fixed-size array, DeviceAddress<T> or a registered struct");       \
  static_assert(::proceduray::detail::field_ok(::proceduray::type_ops<T>, I),                                  \
                #T "::" #m ": the C++ offset or inner layout differs from the " #R " layout; reorder "         \
                "members, add explicit padding members, or use the scalar rule");

/// Registers struct Type for GLSL with layout rule Rule (scalar, std430, std140) and its members in order.
#define PROCEDURAY_STRUCT(Type, Rule, ...) \
  PROCEDURAY_DETAIL_REGISTER(Type, Rule, PROCEDURAY_DETAIL_FIELD, PROCEDURAY_DETAIL_CHECK, __VA_ARGS__)

/// The registration behind PROCEDURAY_STRUCT, with the per-member macros as parameters so that
/// PROCEDURAY_DEFINE_STRUCT (define_struct.hpp) registers (type, name) pairs through the same checks.
#define PROCEDURAY_DETAIL_REGISTER(Type, Rule, FIELD, CHECK, ...)                                              \
  struct ProcedurayFields_##Type;                                                                              \
  [[maybe_unused]] inline ProcedurayFields_##Type proceduray_fields(::proceduray::detail::TypeTag<Type>);      \
  struct ProcedurayFields_##Type {                                                                             \
    static constexpr ::std::string_view glsl_name = #Type;                                                     \
    static constexpr ::proceduray::LayoutRule rule = ::proceduray::LayoutRule::Rule;                           \
    static constexpr ::proceduray::Field fields[] = {PROCEDURAY_DETAIL_FOR_EACH(FIELD, Type, Rule, __VA_ARGS__)}; \
  };                                                                                                           \
  /* defined and [[maybe_unused]]: a registration inside an unnamed namespace is no unused-function */        \
  /* warning (GCC) and no unneeded-internal-declaration warning (clang, which sees it used only in */         \
  /* unevaluated operands) */                                                                                  \
  [[maybe_unused]] inline ProcedurayFields_##Type proceduray_fields(::proceduray::detail::TypeTag<Type>) {      \
    return {};                                                                                                 \
  }                                                                                                            \
  static_assert(::proceduray::detail::PlainStruct<Type>,                                                       \
                #Type ": a GPU-visible struct must be standard-layout and trivially copyable");                \
  static_assert(!::proceduray::is_glsl_reserved(#Type),                                                        \
                #Type ": the struct's name is a reserved GLSL word; rename the struct");                       \
  PROCEDURAY_DETAIL_FOR_EACH(CHECK, Type, Rule, __VA_ARGS__)                                                   \
  static_assert(::proceduray::detail::size_ok(::proceduray::type_ops<Type>),                                   \
                #Type ": sizeof differs from the " #Rule " struct size; list every member and add explicit "   \
                "trailing padding members")
