// The bodies of proceduray/scene/glsl_names.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/glsl_names.hpp"

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
