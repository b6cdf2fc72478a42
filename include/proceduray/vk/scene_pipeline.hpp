// The ray-tracing pipeline of a compiled scene, in two steps with the plan settled between them:
// each planned stage's GLSL read from the shader folders and compiled after its declarations
// (what each stage traces read from its SPIR-V), then the pipeline of the planned groups at the
// plan's recursion depth, with a disk pipeline cache when asked.
//
//   proceduray::vk::SceneStages stages = proceduray::vk::compile_scene_stages(plan, {.shader_dirs = {"shaders"}});
//   proceduray::SbtLayout layout = plan.layout(ctx.limits());   // the device's limits, checked once
//   plan.settle_recursion(stages.traces, ctx.limits(), "Renderer");   // the final depth, in the plan
//   std::unique_ptr<proceduray::vk::Pipeline> pipeline = proceduray::vk::make_scene_pipeline(
//       ctx, plan, std::move(stages), bindings.layouts(), bindings.push_size(), {.shader_dirs = {"shaders"}});
//   std::vector<proceduray::vk::ShaderGroup> groups = proceduray::vk::shader_groups(plan.pipeline());   // for a PipelineDesc
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/scene/plan.hpp>
#include <proceduray/scene/glsl_names.hpp>
#include <proceduray/scene/recursion.hpp>
#include <proceduray/scene/shader_context.hpp>
#include <proceduray/vk/acceleration.hpp>
#include <proceduray/vk/pipeline.hpp>
#include <proceduray/vk/pipeline_cache.hpp>
#include <proceduray/vk/spirv_cache.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace proceduray::vk {

/// How a Renderer finds and compiles its shaders (make_scene_pipeline) and builds its BLASes
/// (SceneAcceleration). Every member has a default.
struct RendererOptions {
  std::vector<std::filesystem::path> shader_dirs;  ///< where the plan's shader names are read; default: the current folder
  /// Keep compiled shaders and the driver's pipeline cache on disk (default on): a second start
  /// skips glslang and most of the driver's compile. Off: neither is read nor written.
  bool cache = true;
  /// Where: default empty, default_cache_dir() ($XDG_CACHE_HOME/proceduray, else ~/.cache/proceduray).
  std::filesystem::path cache_dir;
  /// The pipeline cache file; empty (default): one per device in the cache folder (when `cache`).
  std::filesystem::path pipeline_cache;
  BuildOptions blas{};                   ///< BLAS builds (SceneAcceleration); default compacted, fast trace
  /// Frames a Renderer keeps in flight, 1..max_frames_in_flight (8); default 2: the host records
  /// one frame while the device traces the one before.
  std::uint32_t frames_in_flight = 2;
};

/// A plan's stages compiled, in pipeline().stages order.
struct SceneStages {
  std::vector<std::vector<std::uint32_t>> spirv;  ///< one module per stage
  std::vector<StageTraces> traces;                ///< what each traces (for Plan::settle_recursion)
  double compile_ms = 0;                          ///< glslang, all stages (wall time)
  std::uint32_t spirv_cached = 0;                 ///< stages whose SPIR-V came from the cache
  std::uint32_t spirv_compiled = 0;               ///< stages glslang compiled
};

/// What making the pipeline cost, in milliseconds of wall time.
struct PipelineTimings {
  double compile_ms = 0;         ///< GLSL to SPIR-V (glslang)
  double pipeline_ms = 0;        ///< vkCreateRayTracingPipelinesKHR
  bool pipeline_cached = false;  ///< the pipeline cache file was valid and used
  std::uint32_t spirv_cached = 0;    ///< stages whose SPIR-V came from the cache
  std::uint32_t spirv_compiled = 0;  ///< stages glslang compiled
};

/// The plan's groups as pipeline groups, indices into the plan's stages (in the plan's order,
/// which is the order of the handles the plan's records use).
PROCEDURAY_DECL std::vector<ShaderGroup> shader_groups(const PipelinePlan& planned);

/// The path of shader `name` in the first of `dirs` that has it; throws UsageError listing the folders.
PROCEDURAY_DECL std::string find_shader(std::span<const std::filesystem::path> dirs, const std::string& name);

/// What planned stage `s` traces, from trace_info(its SPIR-V): a payload named like a ray's
/// id (glsl_for's outgoing payloads) is that ray; `payload` (the incoming one) is each ray whose
/// records run the stage; any other name, or none, may be any ray.
PROCEDURAY_DECL StageTraces stage_traces(const proceduray::Plan& plan, std::uint32_t s, const TraceInfo& info);

/// The folder the SPIR-V and pipeline caches go to: empty when RendererOptions::cache is off.
PROCEDURAY_DECL std::filesystem::path scene_cache_dir(const RendererOptions& options);

/// Compiles the plan's stages (RendererOptions: shader folders, SPIR-V cache). Throws UsageError
/// for a missing shader, ShaderCompileError naming the stage, the scene entities that use it, and
/// the file (includes resolved) and line.
PROCEDURAY_DECL SceneStages compile_scene_stages(const proceduray::Plan& plan, const RendererOptions& options);

/// Makes the plan's pipeline from its compiled stages over `set_layouts` and `push_size` bytes of
/// push constants, at the plan's recursion depth. The plan must be checked (layout()) and settled
/// (settle_recursion): its numbers are taken as they are (UsageError when not settled).
PROCEDURAY_DECL std::unique_ptr<Pipeline> make_scene_pipeline(const Context& ctx, const proceduray::Plan& plan,
                                                              SceneStages stages,
                                                              std::span<const VkDescriptorSetLayout> set_layouts,
                                                              std::uint32_t push_size, const RendererOptions& options,
                                                              PipelineTimings* timings = nullptr);

}  // namespace proceduray::vk

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
    const std::string path = find_shader(dirs, stage.shader);
    std::vector<std::uint32_t> spirv;
    try {
      // The plan's declarations: the same text a build step writes (glsl_files.hpp).
      spirv = spirv_cache.compile({.stage = stage.stage, .name = path, .code = read_text_file(path),
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
                                                              PipelineTimings* timings) {
  using Clock = std::chrono::steady_clock;
  const PipelinePlan& planned = plan.pipeline();
  if (!planned.recursion_settled || stages.spirv.size() != planned.stages.size()) {
    throw UsageError("make_scene_pipeline: the plan is not settled for these stages (" +
                     std::to_string(stages.spirv.size()) + " modules for " + std::to_string(planned.stages.size()) +
                     " stages); compile them with compile_scene_stages(plan), then call plan.layout(limits) and "
                     "plan.settle_recursion(traces, limits)");
  }
  PipelineDesc desc;
  for (std::size_t i = 0; i < planned.stages.size(); ++i) desc.add_shader(planned.stages[i].stage, std::move(stages.spirv[i]));
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
