// The bodies of proceduray/scene/shader_context.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/shader_context.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL std::string stage_users(const Plan& plan, std::uint32_t stage) {
  const PipelinePlan& p = plan.pipeline();
  if (stage >= p.stages.size()) return {};
  const ShaderStage kind = p.stages[stage].stage;
  std::string list;
  const auto add = [&](const std::string& item) { list += (list.empty() ? "" : ", ") + item; };
  if (kind == ShaderStage::miss) {
    for (const SbtRecord& rec : plan.records(SbtRegionKind::miss)) {
      if (rec.group != no_index && p.groups[rec.group].general == stage) add("\"" + plan.ray_name(rec.ray) + "\"");
    }
    return list.empty() ? std::string() : "the miss shader of rays " + list;
  }
  for (std::uint32_t g = 0; g < p.groups.size(); ++g) {
    const PlannedGroup& group = p.groups[g];
    const bool uses = group.general == stage || group.closest_hit == stage || group.any_hit == stage ||
                      group.intersection == stage;
    if (!uses) continue;
    if (group.type == GroupType::general) {
      add("\"" + group.name + "\"");
      continue;
    }
    std::string rays;  // the rays whose hit records use the group
    for (const SbtRecord& rec : plan.records(SbtRegionKind::hit)) {
      if (rec.group != g) continue;
      const std::string ray = "\"" + plan.ray_name(rec.ray) + "\"";
      if (rays.find(ray) == std::string::npos) rays += (rays.empty() ? "" : ", ") + ray;
    }
    add("\"" + group.name + "\"" + (rays.empty() ? "" : " (ray " + rays + ")"));
  }
  if (list.empty()) return {};
  switch (kind) {
    case ShaderStage::raygen: return "raygen " + list;
    case ShaderStage::callable: return "callable " + list;
    default: return "hit groups " + list;
  }
}

PROCEDURAY_DECL std::string generated_name_hint(const Plan& plan, ShaderStage stage, std::string_view log) {
  // glslang writes "'trace_glow' : no matching overloaded function found" (or "undeclared identifier").
  // Read by hand: <regex> costs every includer seconds of compile time.
  std::string name;
  for (std::size_t at = log.find("'trace_"); at != std::string_view::npos; at = log.find("'trace_", at + 1)) {
    const std::size_t begin = at + 7, end = log.find('\'', begin);
    if (end == std::string_view::npos || end == begin) break;
    const std::string_view rest = log.substr(end + 1);
    if (rest.starts_with(" : no matching overloaded function found") || rest.starts_with(" : undeclared identifier")) {
      name = std::string(log.substr(begin, end - begin));
      break;
    }
  }
  if (name.empty()) return {};
  std::string rays;
  bool declared = false;
  for (std::uint32_t r = 0; r < plan.ray_count(); ++r) {
    rays += (rays.empty() ? "\"" : ", \"") + plan.ray_name(r) + "\"";
    declared |= glsl_identifier(plan.ray_name(r)) == name;
  }
  const std::string fn = "trace_" + name;
  if (!declared) {
    return fn + " is not generated: the scene declares no ray \"" + name + "\" (its rays: " +
           (rays.empty() ? std::string("none") : rays) + "); call the trace function of one of them, or add the ray "
           "with Scene::add_ray";
  }
  if (stage != ShaderStage::raygen && stage != ShaderStage::miss && stage != ShaderStage::closest_hit) {
    return fn + " is not generated for " + std::string(to_string(stage)) + " shaders: Vulkan lets only raygen, miss "
           "and closest-hit shaders trace rays; trace from the closest-hit shader instead";
  }
  bool tlas = false;
  if (const GlobalSignatureDesc* g = plan.global_signature(); g != nullptr) {
    for (const Binding& b : g->bindings) tlas |= b.kind == BindingKind::acceleration_structure && !b.name.empty();
  }
  if (!tlas) {
    return fn + " is not generated: the global signature names no acceleration structure binding to trace; give "
           "one a name (the default global signature calls it \"tlas\")";
  }
  for (std::uint32_t r = 0; r < plan.ray_count(); ++r) {
    if (glsl_identifier(plan.ray_name(r)) != name) continue;
    bool miss = false;
    for (const SbtRecord& rec : plan.records(SbtRegionKind::miss)) miss |= rec.ray == r && rec.group != no_index;
    if (!miss) {
      return fn + "(origin, tmin, direction, tmax) is not generated: ray \"" + plan.ray_name(r) + "\" has no miss "
             "shader, so a miss would leave its payload uninitialised; pass the payload a miss returns, " + fn +
             "(origin, tmin, direction, tmax, p), or give the ray a miss shader (RayDesc::miss)";
    }
  }
  return {};
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
