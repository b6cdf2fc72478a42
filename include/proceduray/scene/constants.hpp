// Constants a scene's shaders read, declared on the scene in C++ and generated into every stage
// by glsl_for: the one way to hand shaders a host value that is fixed for the pipeline's life
// (per-frame values belong in a uniform or push constants).
//
//   scene.add_constant("max_depth_limit", std::uint32_t{3});   // const uint max_depth_limit = 3u;
//   scene.add_constant("sky", glm::vec3(0.4f, 0.6f, 0.9f));    // const vec3 sky = vec3(0.4, 0.6, 0.9);
//   scene.add_constant("soft_shadows", true);                   // const bool soft_shadows = true;
//   scene.add_define("PAPER_ITERATIVE");                        // #define PAPER_ITERATIVE 1, for #ifdef
//   PROCEDURAY_SCENE_CONSTANTS(scene, flag_shadows, flag_reflections);   // each under its C++ name
//
// Names are checked where they are declared, like every generated name (glsl_names.hpp): a GLSL
// reserved word, a library name or a name another entity declares throws. A define switches code
// in or out before glslang sees it, which a constant cannot: a closest hit that traces only when
// recursive must not trace at all when iterative, or the pipeline needs a deeper recursion.
#pragma once

#include <proceduray/config.hpp>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <variant>

#include "proceduray/shader/glsl_consts.hpp"

namespace proceduray {

/// The value types a scene constant may have (GLSL uint, int, float, bool, vec2, vec3, vec4).
using ConstantValue = std::variant<std::uint32_t, std::int32_t, float, bool, glm::vec2, glm::vec3, glm::vec4>;

/// One constant (or define) a scene declares to its shaders.
struct SceneConstant {
  std::string name;     ///< its GLSL name
  ConstantValue value;  ///< ignored for a define
  bool define = false;  ///< `#define name 1` instead of a constant
  friend bool operator==(const SceneConstant&, const SceneConstant&) = default;
};

/// The GLSL line that declares `c`.
PROCEDURAY_DECL std::string glsl_constant(const SceneConstant& c);

}  // namespace proceduray

#define PROCEDURAY_DETAIL_SCENE_CONSTANT(T, scene, I, name) \
  (scene).add_constant(std::string(::proceduray::detail::glsl_const_name(#name)), name);

/// Declares each named C++ constant on `scene` under its own name: a name GLSL cannot take does
/// not compile (see PROCEDURAY_GLSL_CONSTS). At most 32 names.
#define PROCEDURAY_SCENE_CONSTANTS(scene, ...) \
  do { PROCEDURAY_DETAIL_FOR_EACH(PROCEDURAY_DETAIL_SCENE_CONSTANT, void, scene, __VA_ARGS__) } while (false)

#include "proceduray/scene/constants-inl.hpp"  // the bodies (config.hpp)
