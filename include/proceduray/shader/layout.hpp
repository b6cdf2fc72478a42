// GLSL block layout rules (scalar, std430, std140) computed at compile time, and the check that
// a registered struct's C++ layout equals its rule's layout.
//
//   using proceduray::LayoutRule;
//   constexpr auto& t = proceduray::type_ops<Sphere>;          // Sphere registered with PROCEDURAY_STRUCT
//   static_assert(proceduray::field_offset(t, 1, LayoutRule::std430) == 12);
//   static_assert(proceduray::extent_of(t, LayoutRule::std140).size == 16);
//   static_assert(proceduray::matches_host(t, LayoutRule::scalar));   // offsets, strides, sizes equal C++
//   proceduray::layout_mismatch(t, LayoutRule::std430);         // run time: "" or where they differ
//
// Rules (Vulkan spec, "Offset and Stride Assignment"): scalar aligns everything to its component;
// std430 aligns vec2 to 2 and vec3/vec4 to 4 components, arrays and matrices to their element;
// std140 also rounds array, matrix-column and struct alignment up to 16. A member's offset is the
// previous end rounded up to its alignment. std430/std140 round struct sizes up to the struct's
// alignment; scalar does not (glslang packs the next member into a struct's or an array's tail),
// so under scalar a struct whose C++ sizeof has tail padding needs explicit padding members.
#pragma once

#include <proceduray/shader/glsl_type.hpp>

#include <algorithm>
#include <cstddef>
#include <string>

namespace proceduray {

/// Alignment and size of a type under a rule.
struct Extent {
  std::size_t align = 1;  ///< base alignment in bytes
  std::size_t size = 0;   ///< bytes it occupies (arrays: stride * count)
};

/// v rounded up to a multiple of a (a > 0).
constexpr std::size_t round_up(std::size_t v, std::size_t a) { return (v + a - 1) / a * a; }

constexpr Extent extent_of(const TypeOps& t, LayoutRule rule);

/// Bytes between consecutive elements of an array type under the rule.
constexpr std::size_t array_stride(const TypeOps& array, LayoutRule rule) {
  const Extent e = extent_of(*array.element, rule);
  const std::size_t align = rule == LayoutRule::std140 ? round_up(e.align, 16) : e.align;
  return round_up(e.size, align);
}

/// Bytes between consecutive columns of a (column-major) matrix type under the rule.
constexpr std::size_t matrix_stride(const TypeOps& m, LayoutRule rule) {
  const std::size_t column = m.rows * m.component_size;
  switch (rule) {
    case LayoutRule::scalar: return column;
    case LayoutRule::std430: return round_up(column, m.rows == 2 ? column : 4 * m.component_size);
    case LayoutRule::std140: return round_up(column, 16);
  }
  return column;
}

/// Offset of a struct type's member `index` under the rule.
constexpr std::size_t field_offset(const TypeOps& s, std::size_t index, LayoutRule rule) {
  std::size_t end = 0;
  for (std::size_t i = 0;; ++i) {
    const Extent e = extent_of(*s.fields[i].type, rule);
    const std::size_t offset = round_up(end, e.align);
    if (i == index) return offset;
    end = offset + e.size;
  }
}

/// Alignment and size of a type under the rule.
constexpr Extent extent_of(const TypeOps& t, LayoutRule rule) {
  const bool is140 = rule == LayoutRule::std140;
  switch (t.kind) {
    case TypeKind::scalar: return {t.component_size, t.component_size};
    case TypeKind::address: return {8, 8};
    case TypeKind::vector: {
      const std::size_t c = t.component_size;
      const std::size_t align = rule == LayoutRule::scalar ? c : (t.rows == 2 ? 2 * c : 4 * c);
      return {align, t.rows * c};
    }
    case TypeKind::matrix: {
      const std::size_t c = t.component_size;
      std::size_t align = rule == LayoutRule::scalar ? c : (t.rows == 2 ? 2 * c : 4 * c);
      if (is140) align = round_up(align, 16);
      return {align, matrix_stride(t, rule) * t.columns};
    }
    case TypeKind::array: {
      const Extent e = extent_of(*t.element, rule);
      const std::size_t stride = array_stride(t, rule);
      // scalar (as glslang lays it out): the last element is not padded to the stride.
      const std::size_t size = rule == LayoutRule::scalar && t.count > 0 ? stride * (t.count - 1) + e.size
                                                                          : stride * t.count;
      return {is140 ? round_up(e.align, 16) : e.align, size};
    }
    case TypeKind::structure: {
      std::size_t align = 1, end = 0;
      for (std::size_t i = 0; i < t.field_count; ++i) {
        const Extent e = extent_of(*t.fields[i].type, rule);
        align = std::max(align, e.align);
        end = round_up(end, e.align) + e.size;
      }
      if (is140) align = round_up(align, 16);
      return {align, rule == LayoutRule::scalar ? end : round_up(end, align)};
    }
    case TypeKind::unsupported:
    case TypeKind::unregistered_struct: break;
  }
  return {1, t.cpp_size};
}

/// Whether the C++ offset of a struct's member `index` equals the rule's (members nested inside it not checked).
constexpr bool field_offset_matches(const TypeOps& s, std::size_t index, LayoutRule rule) {
  return field_offset(s, index, rule) == s.fields[index].offset;
}

/// Whether every offset, stride and size inside the type under the rule equals the C++ one.
constexpr bool matches_host(const TypeOps& t, LayoutRule rule) {
  switch (t.kind) {
    case TypeKind::scalar:
    case TypeKind::vector:
    case TypeKind::address: return extent_of(t, rule).size == t.cpp_size;
    case TypeKind::matrix: return matrix_stride(t, rule) * t.columns == t.cpp_size;
    case TypeKind::array: return array_stride(t, rule) == t.element->cpp_size && matches_host(*t.element, rule);
    case TypeKind::structure:
      for (std::size_t i = 0; i < t.field_count; ++i) {
        if (!field_offset_matches(t, i, rule) || !matches_host(*t.fields[i].type, rule)) return false;
      }
      return extent_of(t, rule).size == t.cpp_size;
    case TypeKind::unsupported:
    case TypeKind::unregistered_struct: break;
  }
  return false;
}

/// Whether member `index` of a struct sits where the rule puts it and is laid out inside as the rule says.
constexpr bool field_matches(const TypeOps& s, std::size_t index, LayoutRule rule) {
  return field_offset_matches(s, index, rule) && matches_host(*s.fields[index].type, rule);
}

/// Where the C++ layout of t first differs from the rule's, as text; empty when they match.
inline std::string layout_mismatch(const TypeOps& t, LayoutRule rule, const std::string& path = "") {
  const std::string where = path.empty() ? std::string(t.cpp_name()) : path;
  const std::string r(to_string(rule));
  switch (t.kind) {
    case TypeKind::array:
      if (array_stride(t, rule) != t.element->cpp_size) {
        return where + ": array stride is " + std::to_string(t.element->cpp_size) + " in C++ but " +
               std::to_string(array_stride(t, rule)) + " under " + r;
      }
      return layout_mismatch(*t.element, rule, where + "[]");
    case TypeKind::structure:
      for (std::size_t i = 0; i < t.field_count; ++i) {
        const Field& f = t.fields[i];
        if (!field_offset_matches(t, i, rule)) {
          return where + "::" + std::string(f.name) + ": offset is " + std::to_string(f.offset) + " in C++ but " +
                 std::to_string(field_offset(t, i, rule)) + " under " + r;
        }
        if (std::string inner = layout_mismatch(*f.type, rule, where + "::" + std::string(f.name)); !inner.empty()) {
          return inner;
        }
      }
      [[fallthrough]];
    default:
      if (!matches_host(t, rule)) {
        return where + ": size is " + std::to_string(t.cpp_size) + " in C++ but " +
               std::to_string(extent_of(t, rule).size) + " under " + r;
      }
  }
  return {};
}

}  // namespace proceduray
