// The ray-tracing pipeline of a compiled scene: each planned stage's GLSL read from the shader
// folders and compiled after its declarations, the planned groups, a recursion depth derived
// from what the stages trace (or the declared one, checked against it), and a disk pipeline
// cache when asked.
//
//   proceduray::vk::PipelineTimings timings;
//   std::unique_ptr<proceduray::vk::Pipeline> pipeline = proceduray::vk::make_scene_pipeline(
//       ctx, plan, bindings.layouts(), bindings.push_size(), {.shader_dirs = {"shaders"}}, &timings);
//   timings.compile_ms;   // glslang, all stages
//   std::vector<proceduray::vk::ShaderGroup> groups = proceduray::vk::shader_groups(plan.pipeline());   // for a PipelineDesc
//   std::uint32_t depth = proceduray::vk::pipeline_depth(ctx, plan, traces);   // traces: stage_traces() per stage
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
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace proceduray::vk {

/// How a Renderer finds and compiles its shaders (make_scene_pipeline) and builds its BLASes
/// (SceneAcceleration). Every member has a default.
struct RendererOptions {
  std::vector<std::filesystem::path> shader_dirs;  ///< where the plan's shader names are read; default: the current folder
  /// Replaces the plan's declarations when set, e.g. with files written at build time (glsl_files);
  /// extra_declarations still follow.
  std::function<std::string(ShaderStage, const std::string& name)> declarations;
  /// GLSL every shader gets after the generated declarations (glsl_for): the scene's own constants, say.
  std::string extra_declarations;
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

/// The recursion depth to build the plan's pipeline with, from what its stages trace
/// (scene/recursion.hpp): the derived depth when none was declared; the declared one when it
/// covers the derived depth, or when a cycle leaves the bound to the shaders. Throws UsageError
/// for a declared depth below the derived one or a cycle with no declared depth, and
/// DeviceLimitError for a depth past the device's maxRayRecursionDepth, naming the chain of rays.
PROCEDURAY_DECL std::uint32_t pipeline_depth(const Context& ctx, const proceduray::Plan& plan, std::span<const StageTraces> traces);

/// Compiles the plan's stages and makes its pipeline over `set_layouts` and `push_size` bytes of push
/// constants, at the recursion depth pipeline_depth() gives. Throws UsageError for a missing shader
/// or a depth the shaders exceed, DeviceLimitError past the device's depth, ShaderCompileError
/// naming the stage, the scene entities that use it, and the file (includes resolved) and line.
PROCEDURAY_DECL std::unique_ptr<Pipeline> make_scene_pipeline(const Context& ctx, const proceduray::Plan& plan,
                                                              std::span<const VkDescriptorSetLayout> set_layouts,
                                                              std::uint32_t push_size, RendererOptions options,
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

PROCEDURAY_DECL std::uint32_t pipeline_depth(const Context& ctx, const proceduray::Plan& plan, std::span<const StageTraces> traces) {
  const PipelinePlan& planned = plan.pipeline();
  const RecursionNeed need = recursion_need(plan, traces);
  const std::uint32_t device = ctx.ray_tracing_properties().maxRayRecursionDepth;
  const std::string declared = std::to_string(planned.max_recursion_depth);
  if (!need.bounded && !planned.recursion_depth_declared) {
    throw UsageError("Renderer: the shaders trace in a cycle (" + need.path + "), so rays nest as deep as the shaders "
                     "let them and no depth can be derived; stop the recursion in the shader (a depth counter in the "
                     "payload) and declare that bound with Scene::set_max_recursion_depth(n), n <= " +
                     std::to_string(device) + " on " + ctx.name());
  }
  if (need.bounded && planned.recursion_depth_declared && planned.max_recursion_depth < need.depth) {
    throw UsageError("Renderer: the shaders nest rays " + std::to_string(need.depth) + " deep (" + need.path +
                     ") but the scene declares max recursion depth " + declared + ", which would crash at the nested "
                     "trace; call Scene::set_max_recursion_depth(" + std::to_string(need.depth) + ") or more, or leave "
                     "it undeclared to use the derived depth");
  }
  const std::uint32_t depth = need.bounded && !planned.recursion_depth_declared ? need.depth : planned.max_recursion_depth;
  if (depth > device) {
    throw DeviceLimitError("Renderer: the pipeline needs recursion depth " + std::to_string(depth) +
                           (need.bounded ? " (" + need.path + ")" : std::string(" (declared)")) + " but " + ctx.name() +
                           " allows " + std::to_string(device) + " (maxRayRecursionDepth); trace fewer nested rays "
                           "(iterate in the raygen instead of recursing in closest-hit shaders)");
  }
  return depth;
}

PROCEDURAY_DECL std::unique_ptr<Pipeline> make_scene_pipeline(const Context& ctx, const proceduray::Plan& plan,
                                                              std::span<const VkDescriptorSetLayout> set_layouts,
                                                              std::uint32_t push_size, RendererOptions options,
                                                              PipelineTimings* timings) {
  using Clock = std::chrono::steady_clock;
  auto ms_since = [](Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  };
  if (options.shader_dirs.empty()) options.shader_dirs.push_back(std::filesystem::current_path());
  const PipelinePlan& planned = plan.pipeline();
  PipelineTimings t;
  PipelineDesc desc;
  std::vector<StageTraces> traces;
  const std::filesystem::path cache_dir =
      !options.cache ? std::filesystem::path() : !options.cache_dir.empty() ? options.cache_dir : default_cache_dir();
  SpirvCache spirv_cache(cache_dir.empty() ? cache_dir : cache_dir / "spirv");
  auto start = Clock::now();
  for (const PlannedStage& stage : planned.stages) {
    const std::string path = find_shader(options.shader_dirs, stage.shader);
    std::string preamble = (options.declarations ? options.declarations(stage.stage, stage.shader)
                                                 : stage.declarations) + options.extra_declarations;
    std::vector<std::uint32_t> spirv;
    try {
      spirv = spirv_cache.compile(
          {.stage = stage.stage, .name = path, .code = read_text_file(path), .preamble = std::move(preamble)});
    } catch (const ShaderCompileError& e) {
      // glslang knows the file; the scene knows who runs it and which generated names exist.
      const auto index = static_cast<std::uint32_t>(&stage - planned.stages.data());
      const std::string users = stage_users(plan, index);
      throw e.with_context("make_scene_pipeline: " + std::string(to_string(stage.stage)) + " shader '" + path + "'" +
                               (users.empty() ? std::string() : " (" + users + ")"),
                           generated_name_hint(plan, stage.stage, e.log()));
    }
    traces.push_back(stage_traces(plan, static_cast<std::uint32_t>(traces.size()), trace_info(spirv)));
    desc.add_shader(stage.stage, std::move(spirv));
  }
  t.compile_ms = ms_since(start);
  t.spirv_cached = spirv_cache.hits();
  t.spirv_compiled = spirv_cache.misses();
  const std::uint32_t depth = pipeline_depth(ctx, plan, traces);  // throws
  desc.groups = shader_groups(planned);
  desc.set_layouts.assign(set_layouts.begin(), set_layouts.end());
  desc.push_constant_size = push_size;
  desc.max_recursion_depth = depth;
  std::filesystem::path pipeline_file = options.pipeline_cache;
  if (pipeline_file.empty() && !cache_dir.empty()) pipeline_file = cache_dir / default_pipeline_cache_name(ctx);
  PipelineCache cache(ctx, pipeline_file);
  desc.cache = cache.get();
  start = Clock::now();
  auto pipeline = std::make_unique<Pipeline>(ctx, desc);
  t.pipeline_ms = ms_since(start);
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
