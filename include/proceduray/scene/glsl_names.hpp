// The GLSL names a scene's ids become, and the checks that keep them valid and distinct.
//
//   proceduray::glsl_identifier("primary-2");     // "primary_2": ids become GLSL names
//   auto names = proceduray::ray_glsl_names("shadow");   // shadow, shadow_ray, _flags, _mask, trace_shadow
//   proceduray::check_glsl_names("Scene::add_ray", scene.glsl_names(), names);   // throws on a clash or a reserved word
//
// glsl_for declares a ray's payload under the ray's id, `<ray>_ray`/`_flags`/`_mask`, `trace_<ray>`,
// `layer_<layer>`, `<callable>_callable`/`_data`/`_call`, and each named binding and push constant block.
// Two ids that differ only in characters GLSL does not allow ("primary-2", "primary_2") would
// declare one name twice, and a ray called "sample" or "payload" would collide with GLSL or with
// the library's own names: glslang then blames a line of generated code the user never wrote.
// These checks run where the id is registered (Scene::add_ray, add_layer, add_callable,
// add_global_signature) and once more in compile(), which also sees the struct type names.
#pragma once

#include <proceduray/config.hpp>

#include "proceduray/scene/errors.hpp"
#include "proceduray/shader/glsl_keywords.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray {

/// `name` with every character that may not appear in a GLSL identifier replaced by '_' (and a
/// leading '_' before a digit).
PROCEDURAY_DECL std::string glsl_identifier(std::string_view name);

/// One name generated code declares, and the entity it comes from (for messages).
struct GlslName {
  std::string name;    ///< as declared in GLSL
  std::string origin;  ///< e.g. `ray "primary-2"`
};

/// Names glsl_for declares itself in some stage (incoming payload, hit attributes, record block,
/// callable data, ray count): no id may take them.
inline constexpr std::array<std::string_view, 5> library_glsl_names = {"arguments", "call", "hit", "payload",
                                                                       "ray_count"};

PROCEDURAY_DECL std::string quote_origin(std::string_view kind, std::string_view id);
/// What a ray declares: its outgoing payload under its own name, its three constants and its trace function.
PROCEDURAY_DECL std::vector<GlslName> ray_glsl_names(std::string_view id);
PROCEDURAY_DECL std::vector<GlslName> layer_glsl_names(std::string_view id);
PROCEDURAY_DECL std::vector<GlslName> callable_glsl_names(std::string_view id);
/// A named binding or push constant block of a global signature (unnamed ones are not declared).
PROCEDURAY_DECL std::vector<GlslName> binding_glsl_names(std::string_view name, std::string_view kind);

/// Throws SceneError when a candidate name is a GLSL reserved word or one of the library's own
/// names, DuplicateIdError when it equals a name in `existing` or another candidate's.
PROCEDURAY_DECL void check_glsl_names(std::string_view op, const std::vector<GlslName>& existing,
                                      const std::vector<GlslName>& candidates);

}  // namespace proceduray

#if PROCEDURAY_BODIES

namespace proceduray {

PROCEDURAY_DECL std::string glsl_identifier(std::string_view name) {
  std::string out(name);
  for (char& c : out) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) c = '_';
  }
  if (out.empty() || (out[0] >= '0' && out[0] <= '9')) out.insert(out.begin(), '_');
  return out;
}

PROCEDURAY_DECL std::string quote_origin(std::string_view kind, std::string_view id) {
  return std::string(kind) + " \"" + std::string(id) + "\"";
}

PROCEDURAY_DECL std::vector<GlslName> ray_glsl_names(std::string_view id) {
  const std::string m = glsl_identifier(id), origin = quote_origin("ray", id);
  return {{m, origin}, {m + "_ray", origin}, {m + "_flags", origin}, {m + "_mask", origin}, {"trace_" + m, origin}};
}

PROCEDURAY_DECL std::vector<GlslName> layer_glsl_names(std::string_view id) {
  return {{"layer_" + glsl_identifier(id), quote_origin("layer", id)}};
}

PROCEDURAY_DECL std::vector<GlslName> callable_glsl_names(std::string_view id) {
  const std::string m = glsl_identifier(id), origin = quote_origin("callable", id);
  return {{m + "_callable", origin}, {m + "_data", origin}, {m + "_call", origin}};
}

PROCEDURAY_DECL std::vector<GlslName> binding_glsl_names(std::string_view name, std::string_view kind) {
  if (name.empty()) return {};
  return {{glsl_identifier(name), quote_origin(kind, name)}};
}

PROCEDURAY_DECL void check_glsl_names(std::string_view op, const std::vector<GlslName>& existing,
                                      const std::vector<GlslName>& candidates) {
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const GlslName& c = candidates[i];
    if (is_glsl_reserved(c.name)) {
      throw SceneError(std::string(op) + ": " + c.origin + " would be declared in GLSL as \"" + c.name +
                       "\", a GLSL reserved word (or a gl_ prefix or double underscore); rename it");
    }
    if (std::find(library_glsl_names.begin(), library_glsl_names.end(), c.name) != library_glsl_names.end()) {
      throw SceneError(std::string(op) + ": " + c.origin + " would be declared in GLSL as \"" + c.name +
                       "\", a name the generated declarations use themselves (payload, hit, arguments, call, "
                       "ray_count); rename it");
    }
    const auto clash = [&](const GlslName& other) {
      if (other.name != c.name) return;
      throw DuplicateIdError(std::string(op) + ": " + c.origin + " and " + other.origin +
                             " would both be declared in GLSL as \"" + c.name +
                             "\" (an id becomes a GLSL name with every character other than a letter, digit or _ "
                             "made _, a ray also declares <name>_ray, _flags, _mask and trace_<name>, and a callable "
                             "<name>_callable, _data and _call); rename one");
    };
    for (const GlslName& e : existing) clash(e);
    for (std::size_t j = 0; j < i; ++j) clash(candidates[j]);
  }
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
