// The shader layer's GLSL code generator: text for registered C++ types, deterministic. A scene's
// declarations are made from it by glsl_for (scene/glsl_for.hpp), the one front end that both a
// Renderer (at run time) and proceduray_generate_scene_glsl (at build time) use.
//
//   std::string glsl = proceduray::glsl_declarations(Interface::types);   // #extension lines, buffer
//                                                // references, structs in dependency order
//   glsl += proceduray::glsl_ray_payload(1, proceduray::type_ops<ShadowPayload>, "shadow");  // layout(location = 1) rayPayloadEXT ...
//   glsl += proceduray::glsl_hit_attribute(proceduray::type_ops<SphereHit>, "hit");   // hitAttributeEXT SphereHit hit;
//   glsl += proceduray::glsl_root_arguments(proceduray::type_ops<SphereRecord>, "arguments"); // layout(shaderRecordEXT, scalar) buffer ...
//   glsl += proceduray::glsl_push_constant<Camera>("camera");  // layout(push_constant, std430) uniform ...
//   glsl += proceduray::glsl_uniform<SceneConstants>(0, 2, "constants");  // layout(set = 0, binding = 2, scalar) uniform ...
//   std::string source = proceduray::insert_after_version(user_shader_text, glsl);
//
// A buffer reference for DeviceAddress<T> is named after T: SphereRef for a struct Sphere,
// Vec3Ref for glm::vec3; its elements are `data[]`, so `arguments.spheres.data[i].radius`.
// Generation throws GlslNameError (a proceduray::UsageError) when two different types would get
// the same GLSL name.
#pragma once

#include <proceduray/error.hpp>
#include <proceduray/shader/categories.hpp>

#include <glm/glm.hpp>
#include <proceduray/shader/glsl_type.hpp>
#include <proceduray/shader/layout.hpp>

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray {

/// Two different types would share one GLSL name; the message names both C++ types.
class GlslNameError : public UsageError {
 public:
  using UsageError::UsageError;
};

/// The GLSL type name T gets, e.g. "vec3", "Sphere", "SphereRef" (array extents not included).
inline std::string glsl_type_name(const TypeOps& t);

namespace detail {

inline std::string reference_name(const TypeOps& pointee) {
  std::string base(pointee.glsl_name);
  if (pointee.kind != TypeKind::structure) {
    if (base.ends_with("_t")) base.resize(base.size() - 2);
    if (!base.empty() && base[0] >= 'a' && base[0] <= 'z') base[0] = static_cast<char>(base[0] - 'a' + 'A');
  }
  return base + "Ref";
}

inline const TypeOps& strip_arrays(const TypeOps& t) { return t.kind == TypeKind::array ? strip_arrays(*t.element) : t; }

inline std::string array_suffix(const TypeOps& t) {
  if (t.kind != TypeKind::array) return {};
  std::string out(1, '[');  // appended piecewise: "[" + std::string trips g++ 12's -Wrestrict at -O3
  out += std::to_string(t.count);
  out += ']';
  out += array_suffix(*t.element);
  return out;
}

inline bool uses_int64(const TypeOps& t) {
  const TypeOps& e = strip_arrays(t);
  return e.kind == TypeKind::scalar && e.glsl_name == "uint64_t";
}

inline std::string member_lines(const TypeOps& s) {
  std::string out;
  for (std::size_t i = 0; i < s.field_count; ++i) {
    const Field& f = s.fields[i];
    out += "    " + glsl_type_name(*f.type) + " " + std::string(f.name) + array_suffix(*f.type) + ";\n";
  }
  return out;
}

/// Structs reachable from the roots, each after the structs it contains, and the address targets.
class DeclarationOrder {
 public:
  explicit DeclarationOrder(std::span<const TypeOps* const> roots) {
    for (const TypeOps* root : roots) visit(*root);
    for (std::size_t i = 0; i < m_pointees.size(); ++i) visit(*m_pointees[i]);  // may append more
  }
  const std::vector<const TypeOps*>& structs() const { return m_structs; }
  const std::vector<const TypeOps*>& pointees() const { return m_pointees; }
  bool int64() const { return m_int64; }
  bool scalar() const {
    for (const TypeOps* s : m_structs) {
      if (s->rule == LayoutRule::scalar) return true;
    }
    for (const TypeOps* p : m_pointees) {
      if (p->kind != TypeKind::structure) return true;
    }
    return false;
  }

 private:
  void visit(const TypeOps& type) {
    const TypeOps& t = strip_arrays(type);
    if (t.kind == TypeKind::address) {
      const TypeOps* p = t.pointee();
      add_unique(m_pointees, p);
      if (uses_int64(*p)) m_int64 = true;
      return;
    }
    if (uses_int64(t)) m_int64 = true;
    if (t.kind != TypeKind::structure || contains(m_structs, &t) || contains(m_open, &t)) return;
    m_open.push_back(&t);
    for (std::size_t i = 0; i < t.field_count; ++i) visit(*t.fields[i].type);
    m_open.pop_back();
    m_structs.push_back(&t);
  }
  static bool contains(const std::vector<const TypeOps*>& v, const TypeOps* t) {
    for (const TypeOps* x : v) {
      if (x == t) return true;
    }
    return false;
  }
  static void add_unique(std::vector<const TypeOps*>& v, const TypeOps* t) {
    if (!contains(v, t)) v.push_back(t);
  }

  std::vector<const TypeOps*> m_structs;
  std::vector<const TypeOps*> m_pointees;
  std::vector<const TypeOps*> m_open;
  bool m_int64 = false;
};

inline void check_unique_names(const DeclarationOrder& order) {
  struct Named {
    std::string name;
    const TypeOps* type;
  };
  std::vector<Named> seen;
  auto add = [&](std::string name, const TypeOps* type) {
    for (const Named& n : seen) {
      if (n.name == name && n.type != type) {
        throw GlslNameError("glsl_declarations: the GLSL name '" + name + "' is used by both " +
                            std::string(n.type->cpp_name()) + " and " + std::string(type->cpp_name()) +
                            "; rename one of the C++ types");
      }
    }
    seen.push_back({std::move(name), type});
  };
  for (const TypeOps* s : order.structs()) add(std::string(s->glsl_name), s);
  for (const TypeOps* p : order.pointees()) add(reference_name(*p), p);
}

}  // namespace detail

inline std::string glsl_type_name(const TypeOps& t) {
  const TypeOps& e = detail::strip_arrays(t);
  if (e.kind == TypeKind::address) return detail::reference_name(*e.pointee());
  return std::string(e.glsl_name);
}

/// Declarations for the types reachable from `roots`: #extension lines, buffer_reference forward
/// declarations, structs in dependency order, buffer_reference blocks. `ray_tracing` adds GL_EXT_ray_tracing.
inline std::string glsl_declarations(std::span<const TypeOps* const> roots, bool ray_tracing = true) {
  const detail::DeclarationOrder order(roots);
  detail::check_unique_names(order);
  std::string out = "// Generated by Proceduray from C++ types; do not edit.\n";
  if (ray_tracing) out += "#extension GL_EXT_ray_tracing : require\n";
  if (order.scalar()) out += "#extension GL_EXT_scalar_block_layout : require\n";
  if (!order.pointees().empty()) out += "#extension GL_EXT_buffer_reference : require\n";
  if (order.int64()) out += "#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require\n";
  if (!order.pointees().empty()) out += "\n";
  for (const TypeOps* p : order.pointees()) {
    out += "layout(buffer_reference) buffer " + detail::reference_name(*p) + ";\n";
  }
  for (const TypeOps* s : order.structs()) {
    out += "\nstruct " + std::string(s->glsl_name) + " {\n" + detail::member_lines(*s) + "};\n";
  }
  for (const TypeOps* p : order.pointees()) {
    const LayoutRule rule = p->kind == TypeKind::structure ? p->rule : LayoutRule::scalar;
    out += "\nlayout(buffer_reference, " + std::string(to_string(rule)) +
           ", buffer_reference_align = " + std::to_string(p->cpp_align) + ") buffer " +
           detail::reference_name(*p) + " {\n    " + glsl_type_name(*p) + " data[];\n};\n";
  }
  return out;
}

/// A payload at `location`: `layout(location = N) rayPayloadEXT T name;` (rayPayloadInEXT when incoming).
inline std::string glsl_ray_payload(std::uint32_t location, const TypeOps& t, std::string_view name, bool incoming = false) {
  return "layout(location = " + std::to_string(location) + ") " + (incoming ? "rayPayloadInEXT " : "rayPayloadEXT ") +
         std::string(t.glsl_name) + " " + std::string(name) + ";\n";
}
/// Callable data at `location`: `layout(location = N) callableDataEXT T name;` (callableDataInEXT when incoming).
inline std::string glsl_callable_data(std::uint32_t location, const TypeOps& t, std::string_view name,
                                      bool incoming = false) {
  return "layout(location = " + std::to_string(location) + ") " + (incoming ? "callableDataInEXT " : "callableDataEXT ") +
         std::string(t.glsl_name) + " " + std::string(name) + ";\n";
}
/// Hit attributes, `hitAttributeEXT T name;` (one per stage).
inline std::string glsl_hit_attribute(const TypeOps& t, std::string_view name) {
  return "hitAttributeEXT " + std::string(t.glsl_name) + " " + std::string(name) + ";\n";
}
/// A buffer block with struct t's members under `rule`; `qualifiers` go first in layout(...).
inline std::string glsl_block(const TypeOps& t, LayoutRule rule, std::string_view qualifiers,
                              std::string_view block_name, std::string_view instance_name) {
  return "layout(" + std::string(qualifiers) + ", " + std::string(to_string(rule)) + ") buffer " +
         std::string(block_name) + " {\n" + detail::member_lines(t) + "} " + std::string(instance_name) + ";\n";
}
/// Root arguments: `layout(shaderRecordEXT, rule) buffer TRootArguments {...} name;`.
inline std::string glsl_root_arguments(const TypeOps& t, std::string_view name) {
  return glsl_block(t, t.rule, "shaderRecordEXT", std::string(t.glsl_name) + "RootArguments", name);
}
/// A push-constant block with t's members and rule: `layout(push_constant, rule) uniform TPushConstants {...} name;`.
inline std::string glsl_push_constant(const TypeOps& t, std::string_view name) {
  return "layout(push_constant, " + std::string(to_string(t.rule)) + ") uniform " + std::string(t.glsl_name) +
         "PushConstants {\n" + detail::member_lines(t) + "} " + std::string(name) + ";\n";
}
/// A uniform block: `layout(set = S, binding = B, rule) uniform TUniform {...} name;` (scalar needs the
/// scalarBlockLayout feature, core in Vulkan 1.2).
inline std::string glsl_uniform(const TypeOps& t, std::uint32_t set, std::uint32_t binding, std::string_view name) {
  return "layout(set = " + std::to_string(set) + ", binding = " + std::to_string(binding) + ", " +
         std::string(to_string(t.rule)) + ") uniform " + std::string(t.glsl_name) + "Uniform {\n" +
         detail::member_lines(t) + "} " + std::string(name) + ";\n";
}
/// A read-only storage buffer holding an array of t, read as `name.data[i]`.
inline std::string glsl_storage_buffer(const TypeOps& t, std::uint32_t set, std::uint32_t binding, std::string_view name) {
  const std::string type(t.glsl_name);
  return "layout(set = " + std::to_string(set) + ", binding = " + std::to_string(binding) + ", " +
         std::string(to_string(t.rule)) + ") readonly buffer " + type + "Buffer {\n    " + type + " data[];\n} " +
         std::string(name) + ";\n";
}

/// A push-constant block of T (see glsl_push_constant(const TypeOps&, name)).
template <RegisteredStruct T>
std::string glsl_push_constant(std::string_view name) {
  return glsl_push_constant(type_ops<T>, name);
}
/// A uniform block of T (see glsl_uniform(const TypeOps&, set, binding, name)).
template <RegisteredStruct T>
std::string glsl_uniform(std::uint32_t set, std::uint32_t binding, std::string_view name) {
  return glsl_uniform(type_ops<T>, set, binding, name);
}

/// A GLSL constant with the exact value of a host constant: `const uint name = 3u;`.
inline std::string glsl_const(std::string_view name, std::uint32_t value) {
  return "const uint " + std::string(name) + " = " + std::to_string(value) + "u;\n";
}
/// `const float name = 0.5;`, printed so it reads back as the same float.
inline std::string glsl_const(std::string_view name, float value) {
  char digits[32];
  const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
  std::string text(digits, end);
  if (text.find_first_of(".en") == std::string::npos) text += ".0";
  return "const float " + std::string(name) + " = " + text + ";\n";
}
/// `const vec3 name = vec3(x, y, z);`, each component as glsl_const(float) prints it.
inline std::string glsl_const(std::string_view name, glm::vec3 v) {
  auto value = [](float f) {
    const std::string line = glsl_const("x", f);
    return line.substr(line.find('=') + 2, line.size() - line.find('=') - 4);
  };
  return "const vec3 " + std::string(name) + " = vec3(" + value(v.x) + ", " + value(v.y) + ", " + value(v.z) + ");\n";
}

/// `source` with `generated` inserted on the line after its `#version` line (at the start if it has none).
inline std::string insert_after_version(std::string_view source, std::string_view generated) {
  std::size_t at = 0;
  if (const std::size_t v = source.find("#version"); v != std::string_view::npos) {
    const std::size_t eol = source.find('\n', v);
    at = eol == std::string_view::npos ? source.size() : eol + 1;
  }
  std::string out(source.substr(0, at));
  if (at > 0 && out.back() != '\n') out += '\n';
  out += generated;
  out += "#line ";
  out += std::to_string(1 + static_cast<std::size_t>(std::count(source.begin(), source.begin() + static_cast<std::ptrdiff_t>(at), '\n')));
  out += "\n";
  out += source.substr(at);
  return out;
}

}  // namespace proceduray
