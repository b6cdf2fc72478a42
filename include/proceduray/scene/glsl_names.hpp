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

#include "proceduray/scene/glsl_names-inl.hpp"  // the bodies (config.hpp)
