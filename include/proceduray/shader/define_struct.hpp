// Declare a GPU-visible struct and register it for GLSL in one go, so no member is named twice.
//
//   PROCEDURAY_DEFINE_STRUCT(Material, scalar,
//                            (glm::vec3, albedo),       ///< base colour
//                            (float, reflectance),      ///< Schlick F0
//                            (float[2], roughness));    ///< C arrays work as written
//
// is the same as writing
//
//   struct Material { glm::vec3 albedo; float reflectance; float roughness[2]; };
//   PROCEDURAY_STRUCT(Material, scalar, albedo, reflectance, roughness);
//
// and runs the same checks with the same messages (field_list.hpp): GLSL-able member types,
// no reserved names, each offset and sizeof equal to the rule's. Why a second macro: with
// PROCEDURAY_STRUCT every member is written in the struct and again in the list, and a member
// left out of the list is only caught by the size check when it changes sizeof.
//
// Each member is `(type, name)`. A type containing a comma (std::array<float, 4>) needs an
// alias first (`using Weights = std::array<float, 4>;`), and a bare name without its type is
// not a member: both stop with a static_assert naming the struct and the fix. At most 32 members.
// Use it at namespace scope, where PROCEDURAY_STRUCT may be used.
#pragma once

#include <proceduray/shader/field_list.hpp>

#include <type_traits>

// Is the argument a parenthesized group? 1 for `(a, b)`, 0 for `name`.
#define PROCEDURAY_DETAIL_SECOND_(a, b, ...) b
#define PROCEDURAY_DETAIL_SECOND(...) PROCEDURAY_DETAIL_SECOND_(__VA_ARGS__, 0, )
#define PROCEDURAY_DETAIL_PAREN_PROBE(...) ~, 1
#define PROCEDURAY_DETAIL_IS_PAREN(x) PROCEDURAY_DETAIL_SECOND(PROCEDURAY_DETAIL_PAREN_PROBE x)

// What a member argument is: `pair` for (type, name), `bad` for anything else (up to 8 elements).
#define PROCEDURAY_DETAIL_NINTH_(_1, _2, _3, _4, _5, _6, _7, _8, _9, ...) _9
#define PROCEDURAY_DETAIL_ARITY_KIND(...) \
  PROCEDURAY_DETAIL_NINTH_(__VA_ARGS__, bad, bad, bad, bad, bad, bad, pair, bad, bad)
#define PROCEDURAY_DETAIL_MEMBER_KIND_0(m) bad
#define PROCEDURAY_DETAIL_MEMBER_KIND_1(m) PROCEDURAY_DETAIL_ARITY_KIND m
#define PROCEDURAY_DETAIL_MEMBER_KIND(m) \
  PROCEDURAY_DETAIL_CAT(PROCEDURAY_DETAIL_MEMBER_KIND_, PROCEDURAY_DETAIL_IS_PAREN(m))(m)

// The pieces of a (type, name) pair.
#define PROCEDURAY_DETAIL_PAIR_DECLARE(type, name) ::std::type_identity_t<type> name;
#define PROCEDURAY_DETAIL_PAIR_NAME(type, name) name

// Per member: the declaration inside the struct, and the field and checks of the registration
// (through one more expansion, so the name is plain before PROCEDURAY_DETAIL_FIELD stringizes it).
#define PROCEDURAY_DETAIL_DECLARE_pair(T, m) PROCEDURAY_DETAIL_PAIR_DECLARE m
#define PROCEDURAY_DETAIL_DECLARE_bad(T, m)                                                                    \
  static_assert(false, #T ": member " #m " is not (type, name): write each member as (type, name), and give " \
                          "a type with a comma an alias first (using Weights = std::array<float, 4>;)");
#define PROCEDURAY_DETAIL_DECLARE(T, R, I, m) \
  PROCEDURAY_DETAIL_CAT(PROCEDURAY_DETAIL_DECLARE_, PROCEDURAY_DETAIL_MEMBER_KIND(m))(T, m)
#define PROCEDURAY_DETAIL_WITH_NAME(F, T, R, I, name) F(T, R, I, name)
#define PROCEDURAY_DETAIL_PAIR_FIELD_pair(T, R, I, m) \
  PROCEDURAY_DETAIL_WITH_NAME(PROCEDURAY_DETAIL_FIELD, T, R, I, PROCEDURAY_DETAIL_PAIR_NAME m)
#define PROCEDURAY_DETAIL_PAIR_FIELD_bad(T, R, I, m)
#define PROCEDURAY_DETAIL_PAIR_FIELD(T, R, I, m) \
  PROCEDURAY_DETAIL_CAT(PROCEDURAY_DETAIL_PAIR_FIELD_, PROCEDURAY_DETAIL_MEMBER_KIND(m))(T, R, I, m)
#define PROCEDURAY_DETAIL_PAIR_CHECK_pair(T, R, I, m) \
  PROCEDURAY_DETAIL_WITH_NAME(PROCEDURAY_DETAIL_CHECK, T, R, I, PROCEDURAY_DETAIL_PAIR_NAME m)
#define PROCEDURAY_DETAIL_PAIR_CHECK_bad(T, R, I, m)
#define PROCEDURAY_DETAIL_PAIR_CHECK(T, R, I, m) \
  PROCEDURAY_DETAIL_CAT(PROCEDURAY_DETAIL_PAIR_CHECK_, PROCEDURAY_DETAIL_MEMBER_KIND(m))(T, R, I, m)

/// Declares struct Type with the (type, name) members in order and registers it with layout rule
/// Rule (scalar, std430, std140), as PROCEDURAY_STRUCT does.
#define PROCEDURAY_DEFINE_STRUCT(Type, Rule, ...)                                                      \
  struct Type {                                                                                        \
    PROCEDURAY_DETAIL_FOR_EACH(PROCEDURAY_DETAIL_DECLARE, Type, Rule, __VA_ARGS__)                     \
  };                                                                                                   \
  PROCEDURAY_DETAIL_REGISTER(Type, Rule, PROCEDURAY_DETAIL_PAIR_FIELD, PROCEDURAY_DETAIL_PAIR_CHECK, __VA_ARGS__)
