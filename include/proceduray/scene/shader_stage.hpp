// The ray-tracing shader stages, shared by the scene layer (pipeline plans) and the backend, and
// compute, which no scene holds: vk::compile_glsl compiles it for the benchmarks' compute shaders.
//
//   proceduray::ShaderStage s = proceduray::ShaderStage::intersection;
//   proceduray::to_string(s);   // "intersection"
//   proceduray::SpecConstant c{2000, 1u};   // a stage's specialization constant: id and bits
#pragma once

#include <proceduray/config.hpp>

#include <cstdint>

namespace proceduray {

/// A shader stage of the ray-tracing pipeline (compute: outside it, never in a scene).
enum class ShaderStage : std::uint32_t { raygen, miss, closest_hit, any_hit, intersection, callable, compute };

PROCEDURAY_DECL const char* to_string(ShaderStage stage);

/// One 4-byte specialization constant of a stage (GLSL layout(constant_id = id)): its bits, a
/// uint's, a float's or a bool's (0 or 1).
struct SpecConstant {
  std::uint32_t id = 0;
  std::uint32_t bits = 0;
  friend bool operator==(const SpecConstant&, const SpecConstant&) = default;
};

}  // namespace proceduray

#include "proceduray/scene/shader_stage-inl.hpp"  // the bodies (config.hpp)
