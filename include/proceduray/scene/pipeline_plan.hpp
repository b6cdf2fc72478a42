// The pipeline plan: what a ray-tracing pipeline needs, derived by compile(scene): the shader
// stages and groups records actually reference (each stage with its GLSL declarations), the
// recursion depth the scene declares, and the largest payload, hit attributes and root arguments
// of what the records use.
//
//   const proceduray::PipelinePlan& pipeline = proceduray::compile(scene).pipeline();
//   for (const auto& stage : pipeline.stages) { /* compile stage.shader as stage.stage, after stage.declarations */ }
//   for (const auto& group : pipeline.groups) { /* VkRayTracingShaderGroupCreateInfoKHR; indices into stages */ }
//   // maxPipelineRayRecursionDepth = pipeline.max_recursion_depth;
//   // group handles, fetched in pipeline.groups order, go to Plan::write.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "proceduray/scene/ids.hpp"
#include "proceduray/scene/shader_stage.hpp"

namespace proceduray {

/// Marks an unused stage slot of a group (VK_SHADER_UNUSED_KHR).
inline constexpr std::uint32_t unused_shader = 0xFFFF'FFFFu;

/// One pipeline stage: a shader name the backend compiles for `stage`.
struct PlannedStage {
  ShaderStage stage = ShaderStage::raygen;  ///< its stage
  std::string shader;                       ///< the name the scene used
  std::string declarations;                 ///< its GLSL declarations (glsl_for.hpp)
  friend bool operator==(const PlannedStage&, const PlannedStage&) = default;
};

/// VkRayTracingShaderGroupTypeKHR, without Vulkan.
enum class GroupType : std::uint32_t { general, triangles_hit, procedural_hit };

/// One shader group; stage members index PipelinePlan::stages, unused_shader if none.
struct PlannedGroup {
  GroupType type = GroupType::general;        ///< general for raygen and miss
  std::uint32_t general = unused_shader;      ///< raygen or miss stage
  std::uint32_t closest_hit = unused_shader;  ///< closest-hit stage
  std::uint32_t any_hit = unused_shader;      ///< any-hit stage
  std::uint32_t intersection = unused_shader; ///< intersection stage
  std::string name;                           ///< shader name (general) or hit group id
  HitGroupId hit_group;                       ///< the hit group it came from; invalid for general groups
  std::uint32_t attribute_size = 0;           ///< hit attribute bytes its intersection reports (hit groups)
  friend bool operator==(const PlannedGroup&, const PlannedGroup&) = default;
};

/// Everything a pipeline needs, derived from the scene and its entries.
struct PipelinePlan {
  std::vector<PlannedStage> stages;               ///< used stages, each once: raygen, miss, then hit stages
  std::vector<PlannedGroup> groups;               ///< used groups: raygen, miss, hit groups, callables; handle order
  /// As declared by Scene::set_max_recursion_depth, else 1; after Plan::settle_recursion, the
  /// depth the pipeline is built with (derived from what the stages trace when undeclared).
  std::uint32_t max_recursion_depth = 1;
  /// Whether the depth was declared (Scene::set_max_recursion_depth); default false: settling
  /// derives it, and refuses stages that trace in a cycle.
  bool recursion_depth_declared = false;
  bool recursion_settled = false;  ///< Plan::settle_recursion ran: max_recursion_depth is final
  std::string recursion_path;      ///< when settling derived the depth: the deepest chain of nested rays, for messages
  std::uint32_t max_payload_size = 0;             ///< largest payload of a ray type records use (bytes)
  std::uint32_t max_attribute_size = 0;           ///< largest hit attributes of a used hit group (bytes)
  std::array<std::uint32_t, 4> max_root_arguments_size{};  ///< per region (SbtRegionKind order), bytes after the handle
  GlobalSignatureId global_signature;             ///< invalid when none was set
  std::vector<LocalSignatureId<>> local_signatures;  ///< local signatures used by records, in registration order
  friend bool operator==(const PipelinePlan&, const PipelinePlan&) = default;
};

}  // namespace proceduray
