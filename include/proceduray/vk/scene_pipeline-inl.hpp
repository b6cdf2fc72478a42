// The bodies of proceduray/vk/scene_pipeline.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/scene_pipeline.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL std::vector<ShaderGroup> shader_groups(const PipelinePlan& planned) {
  static constexpr VkRayTracingShaderGroupTypeKHR types[] = {VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR,
                                                             VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR,
                                                             VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR};
  std::vector<ShaderGroup> groups;
  for (const PlannedGroup& g : planned.groups) {
    groups.push_back({types[static_cast<std::uint32_t>(g.type)], g.general, g.closest_hit, g.any_hit, g.intersection});
  }
  return groups;
}

PROCEDURAY_DECL std::string find_shader(std::span<const std::filesystem::path> dirs, const std::string& name) {
  std::string tried;
  for (const auto& dir : dirs) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(dir / name, ec)) return (dir / name).string();
    tried += " '" + dir.string() + "'";
  }
  throw UsageError("Renderer: shader '" + name + "' is not in any shader folder (searched" + tried +
                   "); add its folder to RendererOptions::shader_dirs or fix the name in the scene");
}

PROCEDURAY_DECL StageTraces stage_traces(const proceduray::Plan& plan, std::uint32_t s, const TraceInfo& info) {
  StageTraces out{.any_ray = info.unnamed, .calls = info.calls};
  const PipelinePlan& planned = plan.pipeline();
  auto add = [&](std::uint32_t r) {
    if (std::find(out.rays.begin(), out.rays.end(), r) == out.rays.end()) out.rays.push_back(r);
  };
  for (const std::string& name : info.payloads) {
    bool known = false;
    const auto take = [&](std::uint32_t r) {
      add(r);
      known = true;
    };
    if (name == "payload") {
      for (const SbtRecord& rec : plan.records(SbtRegionKind::miss)) {
        if (rec.group != no_index && planned.groups[rec.group].general == s) take(rec.ray);
      }
      for (const SbtRecord& rec : plan.records(SbtRegionKind::hit)) {
        if (rec.group != no_index && planned.groups[rec.group].closest_hit == s) take(rec.ray);
      }
    }
    for (std::uint32_t r = 0; r < plan.ray_count(); ++r) {
      if (glsl_identifier(plan.ray_name(r)) == name) take(r);
    }
    out.any_ray |= !known;
  }
  return out;
}

PROCEDURAY_DECL std::filesystem::path scene_cache_dir(const RendererOptions& options) {
  if (!options.cache) return {};
  return options.cache_dir.empty() ? default_cache_dir() : options.cache_dir;
}

PROCEDURAY_DECL SceneStages compile_scene_stages(const proceduray::Plan& plan, const RendererOptions& options) {
  using Clock = std::chrono::steady_clock;
  std::vector<std::filesystem::path> dirs = options.shader_dirs;
  if (dirs.empty()) dirs.push_back(std::filesystem::current_path());
  const PipelinePlan& planned = plan.pipeline();
  const std::filesystem::path cache_dir = scene_cache_dir(options);
  SpirvCache spirv_cache(cache_dir.empty() ? cache_dir : cache_dir / "spirv");
  SceneStages out;
  const auto start = Clock::now();
  for (const PlannedStage& stage : planned.stages) {
    // A generated stage (a distance field's) has no file: its includes (the user's field) are
    // found in the shader folders.
    const bool generated = !stage.source.empty();
    const std::string path = generated ? stage.shader : find_shader(dirs, stage.shader);
    std::vector<std::uint32_t> spirv;
    try {
      // The plan's declarations: the same text a build step writes (glsl_files.hpp).
      spirv = spirv_cache.compile({.stage = stage.stage, .name = path,
                                   .code = generated ? stage.source : read_text_file(path),
                                   .include_dirs = generated ? dirs : std::vector<std::filesystem::path>{},
                                   .preamble = stage.declarations});
    } catch (const ShaderCompileError& e) {
      // glslang knows the file; the scene knows who runs it and which generated names exist.
      const auto index = static_cast<std::uint32_t>(&stage - planned.stages.data());
      const std::string users = stage_users(plan, index);
      throw e.with_context("make_scene_pipeline: " + std::string(to_string(stage.stage)) + " shader '" + path + "'" +
                               (users.empty() ? std::string() : " (" + users + ")"),
                           generated_name_hint(plan, stage.stage, e.log()));
    }
    out.traces.push_back(stage_traces(plan, static_cast<std::uint32_t>(out.traces.size()), trace_info(spirv)));
    out.spirv.push_back(std::move(spirv));
  }
  out.compile_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  out.spirv_cached = spirv_cache.hits();
  out.spirv_compiled = spirv_cache.misses();
  return out;
}

PROCEDURAY_DECL std::unique_ptr<Pipeline> make_scene_pipeline(const Context& ctx, const proceduray::Plan& plan,
                                                              SceneStages stages,
                                                              std::span<const VkDescriptorSetLayout> set_layouts,
                                                              std::uint32_t push_size, const RendererOptions& options,
                                                              PipelineTimings* timings,
                                                              std::span<const MarchKnobs> field_knobs) {
  using Clock = std::chrono::steady_clock;
  const PipelinePlan& planned = plan.pipeline();
  if (!planned.recursion_settled || stages.spirv.size() != planned.stages.size()) {
    throw UsageError("make_scene_pipeline: the plan is not settled for these stages (" +
                     std::to_string(stages.spirv.size()) + " modules for " + std::to_string(planned.stages.size()) +
                     " stages); compile them with compile_scene_stages(plan), then call plan.layout(limits) and "
                     "plan.settle_recursion(traces, limits)");
  }
  if (!field_knobs.empty() && field_knobs.size() != plan.fields().size()) {
    throw UsageError("make_scene_pipeline: " + std::to_string(field_knobs.size()) + " field knobs for a plan of " +
                     std::to_string(plan.fields().size()) + " distance fields; pass one per field, or none");
  }
  PipelineDesc desc;
  for (std::size_t i = 0; i < planned.stages.size(); ++i) {
    const std::optional<std::uint32_t> field = planned.stages[i].field;
    desc.add_shader(planned.stages[i].stage, std::move(stages.spirv[i]),
                    field && !field_knobs.empty() ? field_spec_constants(field_knobs[*field]) : std::vector<SpecConstant>{});
  }
  desc.groups = shader_groups(planned);
  desc.set_layouts.assign(set_layouts.begin(), set_layouts.end());
  desc.push_constant_size = push_size;
  desc.max_recursion_depth = planned.max_recursion_depth;
  desc.max_payload_size = planned.max_payload_size;
  desc.max_attribute_size = planned.max_attribute_size;
  desc.planned = true;  // the plan's checks ran: the device's limits and each stage's tracing
  const std::filesystem::path cache_dir = scene_cache_dir(options);
  std::filesystem::path pipeline_file = options.pipeline_cache;
  if (pipeline_file.empty() && !cache_dir.empty()) pipeline_file = cache_dir / default_pipeline_cache_name(ctx);
  PipelineCache cache(ctx, pipeline_file);
  desc.cache = cache.get();
  const auto start = Clock::now();
  auto pipeline = std::make_unique<Pipeline>(ctx, desc);
  PipelineTimings t{.compile_ms = stages.compile_ms, .spirv_cached = stages.spirv_cached,
                    .spirv_compiled = stages.spirv_compiled};
  t.pipeline_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  t.pipeline_cached = cache.loaded();
  try {
    cache.save();
  } catch (const EnvironmentError& e) {  // a cache that cannot be written costs time, never the run
    std::fprintf(stderr, "proceduray: warning: %s; running without a saved pipeline cache\n", e.what());
  }
  if (timings != nullptr) *timings = t;
  return pipeline;
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
