// The bodies of proceduray/vk/pipeline.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/pipeline.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL void check_recursion_depth(std::string_view operation, ShaderStage stage, std::string_view shader,
                                           std::span<const std::uint32_t> spirv, std::uint32_t depth, bool declared,
                                           std::string_view fix) {
  if (stage == ShaderStage::raygen || depth >= 2 || !traces_rays(spirv)) return;
  throw UsageError(std::string(operation) + ": " + to_string(stage) + " shader '" + std::string(shader) +
                   "' calls traceRayEXT, so its rays nest inside the raygen's, but the pipeline's max recursion "
                   "depth is " + std::to_string(depth) + (declared ? "" : " (the default: none was declared)") +
                   ", which would crash at the nested trace; " + std::string(fix) +
                   " with n >= 2 (1 + how many rays deep the nesting goes)");
}

}  // namespace proceduray::vk

namespace proceduray::vk::detail {

PROCEDURAY_DECL VkShaderStageFlagBits vk_stage(ShaderStage s) {
  switch (s) {
    case ShaderStage::raygen: return VK_SHADER_STAGE_RAYGEN_BIT_KHR;
    case ShaderStage::miss: return VK_SHADER_STAGE_MISS_BIT_KHR;
    case ShaderStage::closest_hit: return VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR;
    case ShaderStage::any_hit: return VK_SHADER_STAGE_ANY_HIT_BIT_KHR;
    case ShaderStage::intersection: return VK_SHADER_STAGE_INTERSECTION_BIT_KHR;
    case ShaderStage::callable: return VK_SHADER_STAGE_CALLABLE_BIT_KHR;
    case ShaderStage::compute: return VK_SHADER_STAGE_COMPUTE_BIT;
  }
  return VK_SHADER_STAGE_RAYGEN_BIT_KHR;
}

PROCEDURAY_DECL void check_pipeline_desc(const Context& ctx, const PipelineDesc& desc) {
  const std::uint32_t device_depth = ctx.ray_tracing_properties().maxRayRecursionDepth;
  if (!desc.planned && desc.max_recursion_depth > device_depth) {
    throw DeviceLimitError("Pipeline: max_recursion_depth " + std::to_string(desc.max_recursion_depth) +
                           " exceeds maxRayRecursionDepth " + std::to_string(device_depth) + " of " + ctx.name() +
                           "; trace deeper paths iteratively from the raygen shader");
  }
  const auto shader_count = static_cast<std::uint32_t>(desc.shaders.size());
  auto check_index = [&](std::size_t g, std::uint32_t index, const char* role) {
    if (index != VK_SHADER_UNUSED_KHR && index >= shader_count) {
      throw UsageError("Pipeline: group " + std::to_string(g) + " names " + role + " shader " +
                       std::to_string(index) + " but only " + std::to_string(shader_count) +
                       " shaders were added");
    }
  };
  for (std::size_t g = 0; g < desc.groups.size(); ++g) {
    const ShaderGroup& group = desc.groups[g];
    check_index(g, group.general, "general");
    check_index(g, group.closest_hit, "closest-hit");
    check_index(g, group.any_hit, "any-hit");
    check_index(g, group.intersection, "intersection");
    if (group.type == VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR &&
        group.intersection == VK_SHADER_UNUSED_KHR) {
      throw UsageError("Pipeline: procedural hit group " + std::to_string(g) +
                       " has no intersection shader; procedural geometry needs one");
    }
  }
  for (std::size_t i = 0; i < desc.shaders.size() && !desc.planned; ++i) {
    check_recursion_depth("Pipeline", desc.shaders[i].stage, "PipelineDesc::shaders[" + std::to_string(i) + "]",
                          desc.shaders[i].spirv, desc.max_recursion_depth, true,
                          "set PipelineDesc::max_recursion_depth = n");
  }

}

PROCEDURAY_DECL VkPipeline create_pipeline(const Context& ctx, const PipelineDesc& desc, VkPipelineLayout layout) {
  std::vector<DeviceHandle<VkShaderModule>> modules;
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  // Each stage's map entries and specialization info, sized first: stages point into them.
  std::vector<std::vector<VkSpecializationMapEntry>> entries(desc.shaders.size());
  std::vector<VkSpecializationInfo> specializations(desc.shaders.size());
  for (const auto& shader : desc.shaders) {
    auto info = make<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    info.codeSize = shader.spirv.size() * sizeof(std::uint32_t);
    info.pCode = shader.spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    check(vkCreateShaderModule(ctx.device(), &info, nullptr, &module), "vkCreateShaderModule");
    modules.push_back(own(ctx, module, vkDestroyShaderModule));
    auto stage = make<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    stage.stage = detail::vk_stage(shader.stage);
    stage.module = module;
    stage.pName = "main";
    if (!shader.constants.empty()) {
      const std::size_t i = stages.size();
      for (std::size_t c = 0; c < shader.constants.size(); ++c) {
        entries[i].push_back({shader.constants[c].id, static_cast<std::uint32_t>(c * sizeof(SpecConstant) +
                                                                                 offsetof(SpecConstant, bits)),
                              sizeof(std::uint32_t)});
      }
      specializations[i] = {static_cast<std::uint32_t>(entries[i].size()), entries[i].data(),
                            shader.constants.size() * sizeof(SpecConstant), shader.constants.data()};
      stage.pSpecializationInfo = &specializations[i];
    }
    stages.push_back(stage);
  }
  std::vector<VkRayTracingShaderGroupCreateInfoKHR> groups;
  for (const ShaderGroup& g : desc.groups) {
    auto info = make<VkRayTracingShaderGroupCreateInfoKHR>(VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR);
    info.type = g.type;
    info.generalShader = g.general;
    info.closestHitShader = g.closest_hit;
    info.anyHitShader = g.any_hit;
    info.intersectionShader = g.intersection;
    groups.push_back(info);
  }
  auto info = make<VkRayTracingPipelineCreateInfoKHR>(VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR);
  info.stageCount = static_cast<std::uint32_t>(stages.size());
  info.pStages = stages.data();
  info.groupCount = static_cast<std::uint32_t>(groups.size());
  info.pGroups = groups.data();
  info.maxPipelineRayRecursionDepth = desc.max_recursion_depth;
  info.layout = layout;
  auto interface = make<VkRayTracingPipelineInterfaceCreateInfoKHR>(
      VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_INTERFACE_CREATE_INFO_KHR);
  interface.maxPipelineRayPayloadSize = desc.max_payload_size;
  interface.maxPipelineRayHitAttributeSize = desc.max_attribute_size;
  // The interface may be given only with VK_KHR_pipeline_library enabled (VUID 03595).
  if (ctx.pipeline_library() && (desc.max_payload_size > 0 || desc.max_attribute_size > 0)) {
    info.pLibraryInterface = &interface;
  }
  const VkDynamicState dynamic = VK_DYNAMIC_STATE_RAY_TRACING_PIPELINE_STACK_SIZE_KHR;
  auto dynamic_info = make<VkPipelineDynamicStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
  dynamic_info.dynamicStateCount = 1;
  dynamic_info.pDynamicStates = &dynamic;
  info.pDynamicState = &dynamic_info;
  VkPipeline pipeline = VK_NULL_HANDLE;
  check(ctx.rt().create_ray_tracing_pipelines(ctx.device(), VK_NULL_HANDLE, desc.cache, 1, &info, nullptr, &pipeline),
        "vkCreateRayTracingPipelinesKHR");
  return pipeline;
}

PROCEDURAY_DECL std::uint32_t default_stack_size(const Context& ctx, const PipelineDesc& desc, VkPipeline pipeline) {
  VkDeviceSize raygen = 0, miss = 0, closest = 0, intersect_any = 0, callable = 0;
  auto size = [&](std::uint32_t g, VkShaderGroupShaderKHR which) {
    return ctx.rt().get_ray_tracing_shader_group_stack_size(ctx.device(), pipeline, g, which);
  };
  for (std::uint32_t g = 0; g < desc.groups.size(); ++g) {
    const ShaderGroup& group = desc.groups[g];
    if (group.type == VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR) {
      const VkDeviceSize s = size(g, VK_SHADER_GROUP_SHADER_GENERAL_KHR);
      switch (desc.shaders[group.general].stage) {
        case ShaderStage::raygen: raygen = std::max(raygen, s); break;
        case ShaderStage::miss: miss = std::max(miss, s); break;
        default: callable = std::max(callable, s); break;
      }
      continue;
    }
    if (group.closest_hit != VK_SHADER_UNUSED_KHR) closest = std::max(closest, size(g, VK_SHADER_GROUP_SHADER_CLOSEST_HIT_KHR));
    VkDeviceSize ia = 0;
    if (group.intersection != VK_SHADER_UNUSED_KHR) ia += size(g, VK_SHADER_GROUP_SHADER_INTERSECTION_KHR);
    if (group.any_hit != VK_SHADER_UNUSED_KHR) ia += size(g, VK_SHADER_GROUP_SHADER_ANY_HIT_KHR);
    intersect_any = std::max(intersect_any, ia);
  }
  const VkDeviceSize depth = desc.max_recursion_depth;
  return static_cast<std::uint32_t>(raygen + std::min<VkDeviceSize>(1, depth) * std::max({closest, miss, intersect_any}) +
                                            (depth > 1 ? depth - 1 : 0) * std::max(closest, miss) + 2 * callable);

}

}  // namespace proceduray::vk::detail

namespace proceduray::vk {

PROCEDURAY_DECL Pipeline::Pipeline(const Context& ctx, const PipelineDesc& desc)
    : m_group_count(static_cast<std::uint32_t>(desc.groups.size())),
      m_handle_size(ctx.ray_tracing_properties().shaderGroupHandleSize),
      m_push_constant_size(desc.push_constant_size) {
  detail::check_pipeline_desc(ctx, desc);
  VkPushConstantRange push{all_ray_tracing_stages, 0, desc.push_constant_size};
  auto layout_info = make<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  layout_info.setLayoutCount = static_cast<std::uint32_t>(desc.set_layouts.size());
  layout_info.pSetLayouts = desc.set_layouts.data();
  layout_info.pushConstantRangeCount = desc.push_constant_size > 0 ? 1 : 0;
  layout_info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  check(vkCreatePipelineLayout(ctx.device(), &layout_info, nullptr, &layout), "vkCreatePipelineLayout");
  m_layout = own(ctx, layout, vkDestroyPipelineLayout);

  const VkPipeline pipeline = detail::create_pipeline(ctx, desc, layout);
  m_pipeline = own(ctx, pipeline, vkDestroyPipeline);
  m_stack_size = detail::default_stack_size(ctx, desc, pipeline);
  m_handles.resize(std::size_t{m_group_count} * m_handle_size);
  if (m_group_count > 0) {
    check(ctx.rt().get_ray_tracing_shader_group_handles(ctx.device(), pipeline, 0, m_group_count, m_handles.size(),
                                                        m_handles.data()),
          "vkGetRayTracingShaderGroupHandlesKHR");
  }
}

PROCEDURAY_DECL std::span<const std::byte> Pipeline::group_handle(std::uint32_t group) const {
  if (group >= m_group_count) {
    throw UsageError("Pipeline::group_handle: group " + std::to_string(group) + " does not exist; the pipeline has " +
                     std::to_string(m_group_count) + " groups");
  }
  return std::span<const std::byte>(m_handles).subspan(std::size_t{group} * m_handle_size, m_handle_size);
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
