// A ray-tracing pipeline from compiled shaders and the groups that use them.
//
//   proceduray::vk::PipelineDesc desc;
//   auto rgen = desc.add_shader(ShaderStage::raygen, compile_glsl({.stage = ShaderStage::raygen, .name = "raygen.rgen", .code = rgen_glsl}));
//   auto miss = desc.add_shader(ShaderStage::miss, miss_spirv);             // SPIR-V from compile_glsl
//   auto hit  = desc.add_shader(ShaderStage::closest_hit, hit_spirv);
//   auto isec = desc.add_shader(ShaderStage::intersection, isec_spirv);
//   desc.groups = {ShaderGroup::general_shader(rgen), ShaderGroup::general_shader(miss),
//                  ShaderGroup::procedural(hit, isec)};
//   desc.set_layouts = {set.layout()};
//   desc.push_constant_size = sizeof(Camera);
//   proceduray::vk::Pipeline pipeline(ctx, desc);
//   pipeline.group_handle(2);   // bytes for SBT record of group 2
//
// A shader other than raygen that calls traceRayEXT needs max_recursion_depth >= 2: Pipeline
// refuses less with a UsageError (lavapipe would crash at the nested trace), as does a depth past
// the device's maxRayRecursionDepth with a DeviceLimitError.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/scene/shader_stage.hpp>
#include <proceduray/vk/descriptors.hpp>
#include <proceduray/vk/shader_compiler.hpp>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray::vk {

/// One shader group: a general shader (raygen, miss, callable) or a hit group.
struct ShaderGroup {
  VkRayTracingShaderGroupTypeKHR type = VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR;
  std::uint32_t general = VK_SHADER_UNUSED_KHR;       ///< raygen, miss or callable shader index
  std::uint32_t closest_hit = VK_SHADER_UNUSED_KHR;   ///< shader index or unused
  std::uint32_t any_hit = VK_SHADER_UNUSED_KHR;       ///< shader index or unused
  std::uint32_t intersection = VK_SHADER_UNUSED_KHR;  ///< required for procedural hit groups

  static ShaderGroup general_shader(std::uint32_t shader) { return {VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, shader}; }
  static ShaderGroup procedural(std::uint32_t closest_hit, std::uint32_t intersection,
                                std::uint32_t any_hit = VK_SHADER_UNUSED_KHR) {
    return {VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR, VK_SHADER_UNUSED_KHR, closest_hit, any_hit,
            intersection};
  }
  static ShaderGroup triangles(std::uint32_t closest_hit, std::uint32_t any_hit = VK_SHADER_UNUSED_KHR) {
    return {VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR, VK_SHADER_UNUSED_KHR, closest_hit, any_hit};
  }
};

/// Everything a pipeline is made from.
struct PipelineDesc {
  struct Shader {
    ShaderStage stage;
    std::vector<std::uint32_t> spirv;
    std::vector<SpecConstant> constants;  ///< its specialization constants; none: the module's defaults
  };
  std::vector<Shader> shaders;
  std::vector<ShaderGroup> groups;
  std::vector<VkDescriptorSetLayout> set_layouts;
  std::uint32_t push_constant_size = 0;  ///< bytes of push constants, visible to every stage; default none
  std::uint32_t max_recursion_depth = 1;  ///< deepest traceRayEXT nesting; 1 = raygen traces only
  VkPipelineCache cache = VK_NULL_HANDLE;  ///< e.g. PipelineCache::get(); default none
  /// The largest payload and hit attributes the stages use (bytes), given to the driver as the
  /// pipeline's interface (VkRayTracingPipelineInterfaceCreateInfoKHR) where the device has
  /// pipeline libraries (Context::pipeline_library); 0 (default): not given.
  std::uint32_t max_payload_size = 0;
  std::uint32_t max_attribute_size = 0;
  /// Made from a settled Plan (make_scene_pipeline), whose checks already ran: the recursion depth
  /// against the device and each stage's tracing are not checked again. Default false.
  bool planned = false;

  /// Adds a shader and returns its index for ShaderGroup.
  std::uint32_t add_shader(ShaderStage stage, std::vector<std::uint32_t> spirv, std::vector<SpecConstant> constants = {}) {
    shaders.push_back({stage, std::move(spirv), std::move(constants)});
    return static_cast<std::uint32_t>(shaders.size() - 1);
  }
};

/// Throws UsageError when `spirv`, a `stage` shader named `shader`, traces rays but `depth` leaves
/// it no room: raygen traces at depth 1, any other stage's traces are nested (depth >= 2).
/// `operation` is the user's call, `declared` whether the user set the depth, `fix` how to set it.
PROCEDURAY_DECL void check_recursion_depth(std::string_view operation, ShaderStage stage, std::string_view shader,
                                           std::span<const std::uint32_t> spirv, std::uint32_t depth, bool declared,
                                           std::string_view fix);

namespace detail {
PROCEDURAY_DECL VkShaderStageFlagBits vk_stage(ShaderStage s);
}  // namespace detail

/// A ray-tracing pipeline, its layout and its shader group handles.
class Pipeline {
 public:
  Pipeline(const Context& ctx, const PipelineDesc& desc);

  VkPipeline get() const noexcept { return m_pipeline.get(); }
  VkPipelineLayout layout() const noexcept { return m_layout.get(); }
  std::uint32_t group_count() const noexcept { return m_group_count; }
  std::uint32_t push_constant_size() const noexcept { return m_push_constant_size; }
  /// Stack bytes the pipeline needs at its recursion depth, from the groups' own stack sizes;
  /// trace() sets it (vkCmdSetRayTracingPipelineStackSizeKHR) instead of the driver's worst case.
  std::uint32_t stack_size() const noexcept { return m_stack_size; }
  /// The opaque handle of group `group` (shaderGroupHandleSize bytes) to copy into an SBT record.
  std::span<const std::byte> group_handle(std::uint32_t group) const;

 private:
  DeviceHandle<VkPipelineLayout> m_layout;
  DeviceHandle<VkPipeline> m_pipeline;
  std::uint32_t m_group_count = 0;
  std::uint32_t m_handle_size = 0;
  std::uint32_t m_push_constant_size = 0;
  std::uint32_t m_stack_size = 0;
  std::vector<std::byte> m_handles;
};

namespace detail {

/// Throws for a depth past the device's, a group naming a shader that does not exist, a
/// procedural group without intersection, or a non-raygen shader that traces at depth 1.
PROCEDURAY_DECL void check_pipeline_desc(const Context& ctx, const PipelineDesc& desc);

/// The pipeline over `layout`: one module per shader, the groups, a dynamic stack size.
PROCEDURAY_DECL VkPipeline create_pipeline(const Context& ctx, const PipelineDesc& desc, VkPipelineLayout layout);

/// The spec's default stack size formula, from the sizes the driver reports per group and stage.
PROCEDURAY_DECL std::uint32_t default_stack_size(const Context& ctx, const PipelineDesc& desc, VkPipeline pipeline);

}  // namespace detail

}  // namespace proceduray::vk

#include "proceduray/vk/pipeline-inl.hpp"  // the bodies (config.hpp)
