// The bodies of proceduray/scene/recursion.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/recursion.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL RecursionNeed recursion_need(const Plan& plan, std::span<const StageTraces> traces) {
  const PipelinePlan& pipeline = plan.pipeline();
  detail::RecursionGraph g{plan, traces, {}, std::vector<std::vector<std::uint32_t>>(plan.ray_count()),
                           std::vector<std::uint32_t>(plan.ray_count(), 0), std::vector<std::string>(plan.ray_count()),
                           std::vector<char>(plan.ray_count(), 0), {}, {}};
  auto add_stage = [&](std::uint32_t ray, std::uint32_t stage) {
    if (ray >= plan.ray_count() || stage == unused_shader) return;
    auto& list = g.stages_of_ray[ray];
    if (std::find(list.begin(), list.end(), stage) == list.end()) list.push_back(stage);
  };
  for (const SbtRecord& rec : plan.records(SbtRegionKind::miss)) {
    if (rec.group != no_index) add_stage(rec.ray, pipeline.groups[rec.group].general);
  }
  for (const SbtRecord& rec : plan.records(SbtRegionKind::hit)) {
    if (rec.group != no_index) add_stage(rec.ray, pipeline.groups[rec.group].closest_hit);
  }
  for (const SbtRecord& rec : plan.records(SbtRegionKind::callable)) {
    if (rec.group != no_index) g.callable_stages.push_back(pipeline.groups[rec.group].general);
  }
  RecursionNeed out;
  for (std::uint32_t s = 0; s < pipeline.stages.size() && s < traces.size(); ++s) {
    if (pipeline.stages[s].stage != ShaderStage::raygen) continue;
    for (std::uint32_t r : g.traced(s)) {
      const std::uint32_t n = g.visit(r);
      if (!g.cycle.empty()) return {false, 0, g.stage_name(s) + " > " + g.cycle};
      if (n > out.depth || out.path.empty()) {
        out.depth = std::max(out.depth, n);
        out.path = g.stage_name(s) + " > " + g.chain[r];
      }
    }
  }
  return out;
}

PROCEDURAY_DECL void Plan::settle_recursion(std::span<const StageTraces> traces, const DeviceLimits& limits,
                                            std::string_view operation) {
  const std::string op(operation);
  if (traces.size() != m_pipeline.stages.size()) {
    throw UsageError(op + ": " + std::to_string(traces.size()) + " stage traces for " +
                     std::to_string(m_pipeline.stages.size()) + " stages; give one per pipeline().stages entry");
  }
  const RecursionNeed need = recursion_need(*this, traces);
  const std::string declared = std::to_string(m_pipeline.max_recursion_depth);
  if (!need.bounded && !m_pipeline.recursion_depth_declared) {
    throw UsageError(op + ": the shaders trace in a cycle (" + need.path + "), so rays nest as deep as the shaders "
                     "let them and no depth can be derived; stop the recursion in the shader (a depth counter in the "
                     "payload) and declare that bound with Scene::set_max_recursion_depth(n)");
  }
  if (need.bounded && m_pipeline.recursion_depth_declared && m_pipeline.max_recursion_depth < need.depth) {
    throw UsageError(op + ": the shaders nest rays " + std::to_string(need.depth) + " deep (" + need.path +
                     ") but the scene declares max recursion depth " + declared + ", which would crash at the nested "
                     "trace; call Scene::set_max_recursion_depth(" + std::to_string(need.depth) + ") or more, or leave "
                     "it undeclared to use the derived depth");
  }
  if (!m_pipeline.recursion_depth_declared) {  // derived: the chain says where the depth comes from
    if (need.depth > limits.max_ray_recursion_depth) {
      throw DeviceLimitError(op + ": the shaders nest rays " + std::to_string(need.depth) + " deep (" + need.path +
                             "), " + (limits.device.empty() ? std::string("the device") : limits.device) + " allows " +
                             std::to_string(limits.max_ray_recursion_depth) + " (maxRayRecursionDepth); trace "
                             "iteratively from raygen instead (nested rays cost a level each)");
    }
    m_pipeline.max_recursion_depth = need.depth;
    m_pipeline.recursion_path = need.path;
  }
  m_pipeline.recursion_settled = true;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
