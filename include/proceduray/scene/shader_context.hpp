// What a shader compile error needs to be read by a person: which scene entities use the failing
// stage, and, when the shader called a generated function that does not exist, what does.
//
//   const proceduray::Plan plan = proceduray::compile(scene);
//   proceduray::stage_users(plan, 3);   // `hit groups "ball" (ray "radiance"), "ball_shadow" (ray "shadow")`
//   proceduray::generated_name_hint(plan, proceduray::ShaderStage::closest_hit, log);
//   // "trace_glow is not generated: the scene declares no ray \"glow\" (its rays: \"radiance\", \"shadow\")"
//
// Why: glslang knows neither the scene nor the names it generates. A call to `trace_glow` for a
// ray never declared reads "'trace_glow' : no matching overloaded function found", and the file
// name alone does not say which hit group runs the shader. The backend (vk/scene_pipeline.hpp)
// adds both to ShaderCompileError.
#pragma once

#include <proceduray/config.hpp>

#include "proceduray/scene/glsl_names.hpp"
#include "proceduray/scene/plan.hpp"

#include <cstdint>
#include <string>
#include <string_view>

namespace proceduray {

/// The entities whose groups use planned stage `stage` (an index into plan.pipeline().stages),
/// for messages: `raygen "main.rgen"`, `miss of ray "shadow"`, `hit groups "ball" (ray "radiance")`,
/// `callable group "tint.rcall"`.
PROCEDURAY_DECL std::string stage_users(const Plan& plan, std::uint32_t stage);

/// Why a generated function a failing shader calls does not exist, from glslang's log, or "":
/// `trace_<ray>` for a ray the scene does not declare, in a stage that cannot trace, or in a
/// scene whose global signature names no acceleration structure.
PROCEDURAY_DECL std::string generated_name_hint(const Plan& plan, ShaderStage stage, std::string_view log);

}  // namespace proceduray

#include "proceduray/scene/shader_context-inl.hpp"  // the bodies (config.hpp)
