// The GLSL of a scene's per-pixel outputs (outputs.hpp): each asked-for output's storage image
// and its helper, and an empty macro for every other helper, so shaders call them unconditionally.
//
//   std::string common = proceduray::glsl_outputs(plan.outputs());        // every stage
//   std::string hit = proceduray::glsl_output_hit(plan.outputs());        // closest-hit and any-hit stages
//
// compile() adds both to each stage's declarations (glsl_for.hpp); a shader never writes them.
#pragma once

#include <proceduray/config.hpp>

#include <span>
#include <string>

#include "proceduray/scene/outputs.hpp"

namespace proceduray {

namespace detail {
/// The body of output `o`'s helper, writing `v` at the pixel of this launch.
PROCEDURAY_DECL std::string output_store(Output o);
PROCEDURAY_DECL const char* output_parameter(Output o);
}  // namespace detail

/// Every stage's output declarations: flag bits, PROCEDURAY_OUTPUTS when any output is asked
/// for, and for each output either its image and helper or an empty macro. Macros, not
/// constants, for the flags: an unused constant would still change the SPIR-V.
PROCEDURAY_DECL std::string glsl_outputs(std::span<const PlannedOutput> planned);

/// A hit stage's output_hit(n): t (gl_HitTEXT), normal n and ids of this hit, through the
/// helpers above; an empty macro when the scene asks for none of the three.
PROCEDURAY_DECL std::string glsl_output_hit(std::span<const PlannedOutput> planned);

}  // namespace proceduray

#include "proceduray/scene/outputs_glsl-inl.hpp"  // the bodies (config.hpp)
