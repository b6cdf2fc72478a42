// The GLSL view of a C++ member type: what it is called in GLSL and how it is built.
//
//   const proceduray::TypeOps& t = proceduray::type_ops<glm::vec3>;
//   t.kind == proceduray::TypeKind::vector;  t.glsl_name == "vec3";  t.rows == 3;
//   proceduray::GlslMember<bool>;            // false: bool has no portable GLSL block layout
//
// Supported: float, int32_t, uint32_t, double, uint64_t; glm vecN/ivecN/uvecN/dvecN (N = 2..4);
// glm matCxR of float; fixed-size arrays of these; structs registered with PROCEDURAY_STRUCT
// (see field_list.hpp); DeviceAddress<T>. Everything else reports TypeKind::unsupported.
#pragma once

#include <proceduray/shader/device_address.hpp>
#include <proceduray/shader/layout_rule.hpp>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace proceduray {

/// What kind of GLSL type a member is.
enum class TypeKind : std::uint32_t { unsupported, unregistered_struct, scalar, vector, matrix, array, structure, address };

struct TypeOps;

/// One member of a registered struct: its name, its C++ placement and its type.
struct Field {
  std::string_view name;     ///< the member's name, same in C++ and GLSL
  std::size_t offset = 0;    ///< C++ offsetof
  std::size_t size = 0;      ///< C++ sizeof of the member
  const TypeOps* type = nullptr;
};

/// Compile-time description of one GLSL type (shared by every member of that type).
struct TypeOps {
  TypeKind kind = TypeKind::unsupported;
  std::string_view glsl_name;            ///< scalar/vector/matrix/struct name; empty for arrays and addresses
  std::size_t component_size = 0;        ///< bytes of one scalar component (4 or 8); 0 for aggregates
  std::uint32_t rows = 1;                ///< vector length, or matrix rows
  std::uint32_t columns = 1;             ///< matrix columns; 1 for scalars and vectors
  std::uint32_t count = 0;               ///< array length; 0 unless an array
  const TypeOps* element = nullptr;      ///< array element type
  const TypeOps* (*pointee)() = nullptr; ///< address target, resolved lazily so a struct may point to itself
  const Field* fields = nullptr;         ///< struct members in declaration order
  std::size_t field_count = 0;
  LayoutRule rule = LayoutRule::scalar;  ///< struct: the rule it is registered with
  std::size_t cpp_size = 0;              ///< sizeof on the host
  std::size_t cpp_align = 0;             ///< alignof on the host
  std::string_view (*cpp_name)() = nullptr;  ///< the C++ type's name, for error messages
  const TypeOps* mesh_vertex = nullptr;  ///< MeshRef<V> (shader/mesh_ref.hpp): V; nullptr for other types
  /// The type's own check of a value (proceduray_validate(const T&, std::string_view where), found
  /// by argument-dependent lookup where T is registered); throws UsageError. nullptr: none.
  void (*validate)(const void* value, std::string_view where) = nullptr;
  bool checked = false;  ///< the type, or a member or element of it, has a validate: check_value walks it
};

template <class Vertex>
struct MeshRef;

namespace detail {

/// Tag the registration function is looked up with (argument-dependent lookup finds the user's namespace).
template <class T>
struct TypeTag {};

/// The C++ name of T as the compiler spells it, e.g. "demo::Sphere".
template <class T>
constexpr std::string_view type_name() {
  std::string_view s = __PRETTY_FUNCTION__;
  const std::size_t from = s.find("T = ") + 4;
  const std::size_t to = s.find_first_of(";]", from);
  return s.substr(from, to - from);
}

template <class T>
struct ScalarInfo {
  static constexpr bool known = false;
};
template <> struct ScalarInfo<float> { static constexpr bool known = true; static constexpr std::string_view name = "float"; static constexpr std::string_view prefix = ""; };
template <> struct ScalarInfo<std::int32_t> { static constexpr bool known = true; static constexpr std::string_view name = "int"; static constexpr std::string_view prefix = "i"; };
template <> struct ScalarInfo<std::uint32_t> { static constexpr bool known = true; static constexpr std::string_view name = "uint"; static constexpr std::string_view prefix = "u"; };
template <> struct ScalarInfo<double> { static constexpr bool known = true; static constexpr std::string_view name = "double"; static constexpr std::string_view prefix = "d"; };
template <> struct ScalarInfo<std::uint64_t> { static constexpr bool known = true; static constexpr std::string_view name = "uint64_t"; static constexpr std::string_view prefix = ""; };

constexpr std::string_view vector_name(std::string_view prefix, int n) {
  constexpr std::string_view f[] = {"vec2", "vec3", "vec4"}, i[] = {"ivec2", "ivec3", "ivec4"},
                             u[] = {"uvec2", "uvec3", "uvec4"}, d[] = {"dvec2", "dvec3", "dvec4"};
  const std::string_view* table = prefix == "i" ? i : prefix == "u" ? u : prefix == "d" ? d : f;
  return table[n - 2];
}

constexpr std::string_view matrix_name(int columns, int rows) {
  constexpr std::string_view names[3][3] = {{"mat2", "mat2x3", "mat2x4"},
                                            {"mat3x2", "mat3", "mat3x4"},
                                            {"mat4x2", "mat4x3", "mat4"}};
  return names[columns - 2][rows - 2];
}

template <class T>
struct IsGlm : std::false_type {};
template <glm::length_t N, class T, glm::qualifier Q>
struct IsGlm<glm::vec<N, T, Q>> : std::true_type {};
template <glm::length_t C, glm::length_t R, class T, glm::qualifier Q>
struct IsGlm<glm::mat<C, R, T, Q>> : std::true_type {};

template <class T>
struct IsMeshRef : std::false_type {};
template <class V>
struct IsMeshRef<MeshRef<V>> : std::true_type {};

template <class T>
struct IsAddress : std::false_type {};
template <class T>
struct IsAddress<DeviceAddress<T>> : std::true_type {};

template <class T>
constexpr TypeOps make_type_ops();

/// A type whose values the library checks before they reach a shader (shader/value_check.hpp).
template <class T>
concept HasValidator = requires(const T& value) { proceduray_validate(value, std::string_view{}); };

template <HasValidator T>
void validate_erased(const void* value, std::string_view where) {
  proceduray_validate(*static_cast<const T*>(value), where);
}

constexpr bool any_field_checked(const Field* fields, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    if (fields[i].type->checked) return true;
  }
  return false;
}

}  // namespace detail

/// True when T was registered with PROCEDURAY_STRUCT (visible at this point of the program).
template <class T>
concept RegisteredStruct = requires { proceduray_fields(detail::TypeTag<T>{}); };

/// The field list type PROCEDURAY_STRUCT generated for T (has glsl_name, rule, fields).
template <RegisteredStruct T>
using FieldsOf = decltype(proceduray_fields(detail::TypeTag<T>{}));

/// The GLSL description of T; kind is unsupported when T has no GLSL equivalent.
template <class T>
inline constexpr TypeOps type_ops = detail::make_type_ops<T>();

namespace detail {

// Deliberately not constexpr: its body is instantiated at the end of the translation unit,
// after every registration, so `struct Node { DeviceAddress<Node> next; }` works.
template <class T>
const TypeOps* pointee_ops() {
  return &type_ops<T>;
}

template <class T>
constexpr TypeOps make_type_ops() {
  TypeOps t;
  t.cpp_name = &type_name<T>;
  if constexpr (std::is_array_v<T>) {
    t.kind = TypeKind::array;
    t.count = static_cast<std::uint32_t>(std::extent_v<T>);
    t.element = &type_ops<std::remove_extent_t<T>>;
  } else if constexpr (ScalarInfo<T>::known) {
    t.kind = TypeKind::scalar;
    t.glsl_name = ScalarInfo<T>::name;
    t.component_size = sizeof(T);
  } else if constexpr (std::is_enum_v<T>) {
    // A typed knob: in GLSL the underlying int or uint, whose consts name its values.
    using U = std::underlying_type_t<T>;
    if constexpr (std::is_same_v<U, std::uint32_t> || std::is_same_v<U, std::int32_t>) {
      t.kind = TypeKind::scalar;
      t.glsl_name = ScalarInfo<U>::name;
      t.component_size = sizeof(U);
    }
  } else if constexpr (IsGlm<T>::value) {
    using C = typename T::value_type;
    if constexpr (requires { typename T::col_type; }) {
      t.kind = std::is_same_v<C, float> ? TypeKind::matrix : TypeKind::unsupported;
      t.columns = static_cast<std::uint32_t>(T::length());
      t.rows = static_cast<std::uint32_t>(T::col_type::length());
      t.glsl_name = matrix_name(static_cast<int>(t.columns), static_cast<int>(t.rows));
      t.component_size = sizeof(C);
    } else if constexpr (ScalarInfo<C>::known && !std::is_same_v<C, std::uint64_t>) {
      t.rows = static_cast<std::uint32_t>(T::length());
      t.kind = t.rows >= 2 ? TypeKind::vector : TypeKind::unsupported;
      t.glsl_name = t.rows >= 2 ? vector_name(ScalarInfo<C>::prefix, static_cast<int>(t.rows)) : "";
      t.component_size = sizeof(C);
    }
  } else if constexpr (IsAddress<T>::value) {
    t.kind = TypeKind::address;
    t.pointee = &pointee_ops<typename T::element_type>;
  } else if constexpr (RegisteredStruct<T>) {
    using F = FieldsOf<T>;
    t.kind = TypeKind::structure;
    t.glsl_name = F::glsl_name;
    t.fields = F::fields;
    t.field_count = sizeof(F::fields) / sizeof(Field);
    t.rule = F::rule;
    if constexpr (IsMeshRef<T>::value) t.mesh_vertex = &type_ops<typename T::vertex_type>;
    t.checked = any_field_checked(t.fields, t.field_count);
  } else if constexpr (std::is_class_v<T>) {
    t.kind = TypeKind::unregistered_struct;
  }
  if constexpr (std::is_array_v<T>) t.checked = t.element->checked;
  if constexpr (HasValidator<T>) {
    t.validate = &validate_erased<T>;
    t.checked = true;
  }
  if constexpr (!std::is_void_v<T> && !std::is_function_v<T> && !std::is_reference_v<T>) {
    t.cpp_size = sizeof(T);
    t.cpp_align = alignof(T);
  }
  return t;
}

}  // namespace detail

namespace detail {

template <class T>
constexpr bool is_glsl_member() {
  if constexpr (std::is_array_v<T>) {
    return is_glsl_member<std::remove_extent_t<T>>();
  } else if constexpr (IsAddress<T>::value) {
    using P = typename T::element_type;
    return !std::is_array_v<P> && !IsAddress<P>::value && is_glsl_member<P>();
  } else {
    return type_ops<T>.kind != TypeKind::unsupported && type_ops<T>.kind != TypeKind::unregistered_struct;
  }
}

}  // namespace detail

/// True when T can be a member of a registered struct: no unsupported type anywhere inside it.
/// (Registered nested structs count; their own members were checked when they were registered.)
template <class T>
concept GlslMember = detail::is_glsl_member<T>();

namespace detail {

template <class T>
constexpr bool registered_if_struct() {
  using E = std::remove_all_extents_t<T>;
  if constexpr (IsAddress<E>::value) {
    return registered_if_struct<typename E::element_type>();
  } else {
    return type_ops<E>.kind != TypeKind::unregistered_struct;
  }
}

}  // namespace detail

/// True unless T (an array element, an address target) is a class type neither GLSL knows nor PROCEDURAY_STRUCT registered.
template <class T>
concept RegisteredIfStruct = detail::registered_if_struct<T>();

}  // namespace proceduray
