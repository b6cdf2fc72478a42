// Host constants as GLSL constants, each named once: the name is the C++ name.
//
//   inline constexpr std::uint32_t flag_shadows = 1u, max_depth = 3;
//   inline constexpr float exposure = 2.2f;
//   std::string glsl = PROCEDURAY_GLSL_CONSTS(flag_shadows, max_depth, exposure);
//   // const uint flag_shadows = 1u;  const uint max_depth = 3u;  const float exposure = 2.2;
//
// Why: glsl_const("flag_shadows", flag_shadows) writes each name twice, and a renamed C++
// constant silently keeps its old GLSL name. Each argument must name a constant of a type
// glsl_const takes (std::uint32_t, float, glm::vec3) that GLSL may use as an identifier; any other
// type does not compile (no glsl_const overload matches). A qualified name (ns::flag) or a reserved
// GLSL word is no GLSL name: it does not compile either; bring the name in scope with `using`.
// At most 32 names.
#pragma once

#include <proceduray/shader/field_list.hpp>
#include <proceduray/shader/glsl_codegen.hpp>
#include <proceduray/shader/glsl_keywords.hpp>

#include <string>
#include <string_view>

namespace proceduray::detail {
/// `name` when it is a GLSL identifier and no reserved word; a compile error (the throw) otherwise.
consteval std::string_view glsl_const_name(std::string_view name) {
  bool identifier = !name.empty() && !(name[0] >= '0' && name[0] <= '9');
  for (char c : name) {
    identifier = identifier && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_');
  }
  // The compiler shows this line: the message is the diagnostic.
  if (!identifier || is_glsl_reserved(name)) throw "PROCEDURAY_GLSL_CONSTS: not a plain GLSL name; use plain names";
  return name;
}
}  // namespace proceduray::detail

#define PROCEDURAY_DETAIL_GLSL_CONST(T, R, I, name) \
  +::proceduray::glsl_const(::proceduray::detail::glsl_const_name(#name), name)

/// A std::string with `const <type> <name> = <value>;` for each named constant, in order.
#define PROCEDURAY_GLSL_CONSTS(...) \
  (::std::string() PROCEDURAY_DETAIL_FOR_EACH(PROCEDURAY_DETAIL_GLSL_CONST, _, _, __VA_ARGS__))
