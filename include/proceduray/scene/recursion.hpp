// How deep traceRayEXT calls nest, derived from which rays each shader stage traces: the depth a
// pipeline must be built with, or the cycle that makes it depend on the shaders alone.
//
//   std::vector<proceduray::StageTraces> traces(plan.pipeline().stages.size());   // per stage (vk: trace_info(spirv))
//   proceduray::RecursionNeed need = proceduray::recursion_need(plan, traces);
//   need.bounded;   // false: a stage's rays reach that stage again (reflections): no static bound
//   need.depth;     // when bounded: the deepest nesting, 1 = raygen traces only
//   need.path;      // the deepest chain (or the cycle), for messages
//
// A ray R runs its miss shader and the closest-hit shaders of the hit groups its records use
// (any-hit and intersection shaders cannot trace); a stage that calls executeCallableEXT also
// traces what any callable traces. need(R) = 1 + the deepest need of the rays those stages trace.
// A pipeline built with less than the need crashes at the nested trace (lavapipe: bus error),
// and one built with more than the device allows is refused: the renderer checks both before
// making the pipeline (vk/scene_pipeline.hpp).
#pragma once

#include <proceduray/config.hpp>

#include "proceduray/error.hpp"
#include "proceduray/scene/plan.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <span>
#include <string>
#include <vector>

namespace proceduray {

/// What one stage's code traces and calls.
struct StageTraces {
  std::vector<std::uint32_t> rays;  ///< ray indices it traces (its payloads' locations)
  bool any_ray = false;             ///< traces with a payload location that is no ray index: any ray, to be safe
  bool calls = false;               ///< calls executeCallableEXT
};

/// The nesting the stages can reach.
struct RecursionNeed {
  bool bounded = true;     ///< false when a cycle lets rays nest as deep as the shaders allow
  std::uint32_t depth = 1;  ///< when bounded: the deepest nesting (1 = raygen traces only)
  std::string path;        ///< the deepest chain, or the cycle, e.g. `raygen 'a.rgen' > ray "radiance" > ...`
};

namespace detail {

struct RecursionGraph {
  const Plan& plan;
  std::span<const StageTraces> traces;
  std::vector<std::uint32_t> callable_stages;
  std::vector<std::vector<std::uint32_t>> stages_of_ray;  // stages a ray runs that may trace
  std::vector<std::uint32_t> need;                        // per ray; 0 = not computed
  std::vector<std::string> chain;                         // per ray: the deepest chain below it
  std::vector<char> state;                                // 0 new, 1 on the stack, 2 done
  std::string cycle;

  std::string stage_name(std::uint32_t s) const {
    const PlannedStage& st = plan.pipeline().stages[s];
    return std::string(to_string(st.stage)) + " '" + st.shader + "'";
  }
  std::string ray_name(std::uint32_t r) const { return "ray \"" + plan.ray_name(r) + "\""; }

  /// The rays stage `s` traces, callables included; every ray when unknown.
  std::vector<std::uint32_t> traced(std::uint32_t s) const {
    std::vector<char> in(plan.ray_count(), 0);
    bool all = false;
    auto add = [&](const StageTraces& t) {
      all |= t.any_ray;
      for (std::uint32_t r : t.rays) {
        if (r < in.size()) in[r] = 1;
        else all = true;
      }
    };
    add(traces[s]);
    if (traces[s].calls) {
      for (std::uint32_t c : callable_stages) add(traces[c]);
    }
    std::vector<std::uint32_t> out;
    for (std::uint32_t r = 0; r < in.size(); ++r) {
      if (all || in[r]) out.push_back(r);
    }
    return out;
  }

  std::vector<std::pair<std::uint32_t, std::string>> stack;  // (ray, "ray ... > stage ...") on the way down

  /// need(r); sets `cycle` (the loop, as text) and returns 0 when r reaches itself.
  std::uint32_t visit(std::uint32_t r) {
    if (state[r] == 2) return need[r];
    if (state[r] == 1) {
      std::size_t from = 0;
      while (stack[from].first != r) ++from;
      for (std::size_t i = from; i < stack.size(); ++i) cycle += stack[i].second + " > ";
      cycle += ray_name(r);
      return 0;
    }
    state[r] = 1;
    std::uint32_t deepest = 0;
    std::string below;
    for (std::uint32_t s : stages_of_ray[r]) {
      stack.emplace_back(r, ray_name(r) + " > " + stage_name(s));
      for (std::uint32_t next : traced(s)) {
        const std::uint32_t n = visit(next);
        if (!cycle.empty()) return 0;
        if (n > deepest) {
          deepest = n;
          below = " > " + stage_name(s) + " > " + chain[next];
        }
      }
      stack.pop_back();
    }
    state[r] = 2;
    need[r] = 1 + deepest;
    chain[r] = ray_name(r) + below;
    return need[r];
  }
};

}  // namespace detail

/// The nesting `traces` (one per stage of plan.pipeline().stages) can reach.
PROCEDURAY_DECL RecursionNeed recursion_need(const Plan& plan, std::span<const StageTraces> traces);

}  // namespace proceduray

#include "proceduray/scene/recursion-inl.hpp"  // the bodies (config.hpp)
