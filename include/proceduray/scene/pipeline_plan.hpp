// The pipeline plan: what a ray-tracing pipeline needs, derived only from a built shader
// table: the shader stages and groups records actually reference, the recursion depth the
// scene declares, and the largest payload, hit attributes and record data.
//
//   const proceduray::PipelinePlan& plan = sbt.plan();
//   for (const auto& stage : plan.stages)  { /* compile stage.shader as stage.stage */ }
//   for (const auto& group : plan.groups)  { /* VkRayTracingShaderGroupCreateInfoKHR; indices into stages */ }
//   // maxPipelineRayRecursionDepth = plan.max_recursion_depth;
//   // group handles, fetched in plan.groups order, go to ShaderBindingTable::write.
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
};

/// Everything a pipeline needs, derived from the scene and its entries.
struct PipelinePlan {
  std::vector<PlannedStage> stages;               ///< used stages, each once: raygen, miss, then hit stages
  std::vector<PlannedGroup> groups;               ///< used groups: raygen, miss, hit groups, callables; handle order
  std::uint32_t max_recursion_depth = 1;          ///< as declared by ShaderTable::set_max_recursion_depth
  /// Whether the depth was declared (ShaderTable::set_max_recursion_depth); default false: the
  /// backend refuses a pipeline whose non-raygen stages trace rays at an undeclared depth.
  bool recursion_depth_declared = false;
  std::uint32_t max_payload_size = 0;             ///< largest ray payload (bytes)
  std::uint32_t max_attribute_size = 0;           ///< largest hit attributes of a used hit group (bytes)
  std::array<std::uint32_t, 4> max_record_data_size{};  ///< per region (SbtRegionKind order), bytes after the handle
  GlobalSignatureId global_signature;             ///< invalid when none was set
  std::vector<LocalSignatureId<>> local_signatures;  ///< local signatures used by records, in registration order
};

}  // namespace proceduray
