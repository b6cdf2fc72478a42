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
  /// Compile each distance field's knobs into its intersection (default on): the driver drops the
  /// methods it does not use, so the pipeline builds faster and traces with fewer branches; a
  /// knob change (Renderer::set_field_knobs) builds the pipeline again before the next frame. Off:
  /// the general variant reads the knobs per ray from a buffer, so a sweep or a viewer changes
  /// them for free. Both render the same image.
  bool specialize_fields = true;
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
/// `field_knobs`, one per Plan::fields() entry, are compiled into the fields' intersections
/// (field_spec_constants); empty: the general variant, which reads them from the buffer.
PROCEDURAY_DECL std::unique_ptr<Pipeline> make_scene_pipeline(const Context& ctx, const proceduray::Plan& plan,
                                                              SceneStages stages,
                                                              std::span<const VkDescriptorSetLayout> set_layouts,
                                                              std::uint32_t push_size, const RendererOptions& options,
                                                              PipelineTimings* timings = nullptr,
                                                              std::span<const MarchKnobs> field_knobs = {});

}  // namespace proceduray::vk

#include "proceduray/vk/scene_pipeline-inl.hpp"  // the bodies (config.hpp)
