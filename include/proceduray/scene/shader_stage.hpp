// The ray-tracing shader stages, shared by the scene layer (pipeline plans) and the backend, and
// compute, which no scene holds: vk::compile_glsl compiles it for the benchmarks' compute shaders.
//
//   proceduray::ShaderStage s = proceduray::ShaderStage::intersection;
//   proceduray::to_string(s);   // "intersection"
#pragma once

#include <proceduray/config.hpp>

#include <cstdint>

namespace proceduray {

/// A shader stage of the ray-tracing pipeline (compute: outside it, never in a scene).
enum class ShaderStage : std::uint32_t { raygen, miss, closest_hit, any_hit, intersection, callable, compute };

PROCEDURAY_DECL const char* to_string(ShaderStage stage);

}  // namespace proceduray

#include "proceduray/scene/shader_stage-inl.hpp"  // the bodies (config.hpp)
