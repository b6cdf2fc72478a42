// The bodies of proceduray/scene/compile.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/compile.hpp"
#include "proceduray/scene/uniform_slot.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL void PlanBuilder::outputs() {
  if (s.outputs().empty()) return;
  if (!out.m_global) out.m_global = GlobalSignatureDesc{};
  std::uint32_t next = 0;
  for (const Binding& b : out.m_global->bindings) {
    if (b.set == 0) next = std::max(next, b.binding + 1);
  }
  s.outputs().each([&](Output o) {
    out.m_outputs.push_back({o, next});
    out.m_global->bindings.push_back({BindingKind::output_image, next, 0, 1, "", nullptr});
    ++next;
  });
}

PROCEDURAY_DECL void PlanBuilder::depth_counter() {
  // A derived depth is exact; a declared one may be less than shaders that trace in a cycle would
  // nest, and past the pipeline's depth a trace crashes the device. The counter image stops them.
  if (!s.max_recursion_depth() || detail::trace_target(out).empty()) return;  // no depth, or no trace functions
  std::uint32_t next = 0;
  for (const Binding& b : out.m_global->bindings) {
    if (b.set == 0) next = std::max(next, b.binding + 1);
  }
  out.m_depth_binding = next;
  out.m_global->bindings.push_back({BindingKind::output_image, next, 0, 1, "", nullptr});
}

PROCEDURAY_DECL void PlanBuilder::check_parameter(const DistanceField& f, const FieldParameter& p) const {
  if (p.record) return;  // add_distance_field checked the records' type
  for (const Binding& b : out.m_global->bindings) {
    if (b.kind == BindingKind::uniform_buffer && b.name == p.block && b.type == p.block_type) return;
  }
  throw SceneError("compile: distance field \"" + f.id + "\" takes the parameter " + p.block + "." + p.member +
                   ", but the global signature declares no uniform " + std::string(p.block_type->glsl_name) + " " +
                   p.block + "; add that UniformSlot to the global signature (set_global_signature)");
}

PROCEDURAY_DECL void PlanBuilder::fields() {
  if (s.fields().empty()) return;
  if (!out.m_global) out.m_global = GlobalSignatureDesc{};
  std::uint32_t next = 0;
  for (const Binding& b : out.m_global->bindings) {
    if (b.set == 0) next = std::max(next, b.binding + 1);
  }
  out.m_field_binding = next;
  out.m_global->bindings.push_back(StorageSlot<FieldSettings>{.binding = next, .name = field_settings_name});
  for (const DistanceField& f : s.fields()) {
    for (const FieldParameter& p : f.parameters) check_parameter(f, p);
    PlannedField planned{f, s.geometry_id(f.id), field_capabilities(f), std::nullopt, {}, {}};
    if (s.error_budget()) {
      planned.pick = pick_setting(f, *s.error_budget(), "compile");
      planned.caps.defaults = planned.pick->knobs;
      planned.pick_device = s.error_budget()->table.device();
      planned.pick_source = s.error_budget()->table.source();
    }
    out.m_fields.push_back(std::move(planned));
  }
  // Every stage of a field's intersection (one per any-hit it pairs with) compiles its source.
  for (PlannedStage& stage : out.m_pipeline.stages) {
    if (stage.stage != ShaderStage::intersection) continue;
    for (std::uint32_t i = 0; i < s.fields().size(); ++i) {
      if (stage.shader != field_stage_name(s.fields()[i])) continue;
      stage.source = field_stage_source(s.fields()[i], i);
      stage.field = i;
    }
  }
}

PROCEDURAY_DECL void PlanBuilder::pipeline() {
  PipelinePlan& plan = out.m_pipeline;
  plan.max_recursion_depth = s.max_recursion_depth().value_or(1);
  plan.recursion_depth_declared = s.max_recursion_depth().has_value();
  plan.global_signature = s.pipeline_global_signature();
  if (plan.global_signature.valid()) out.m_global = s.global_signature(plan.global_signature).desc;
  outputs();
  depth_counter();
  // A stage is shared by every group that names it, except that an intersection shader gets one
  // stage per any-hit shader it is paired with: lavapipe (Mesa 25.0) binds the any-hit of the
  // first group to an intersection stage for every group sharing it.
  std::map<std::tuple<ShaderStage, std::string, std::string>, std::uint32_t> stage_of;
  auto stage = [&](ShaderStage kind, const std::string& name, const std::string& paired = {}) {
    if (name.empty()) return unused_shader;
    auto [it, inserted] = stage_of.try_emplace({kind, name, paired}, static_cast<std::uint32_t>(plan.stages.size()));
    if (inserted) plan.stages.push_back(PlannedStage{kind, name, {}});
    return it->second;
  };
  std::map<std::pair<ShaderStage, std::string>, std::uint32_t> general_group;
  auto general = [&](ShaderStage kind, const std::string& name) {
    auto [it, inserted] = general_group.try_emplace({kind, name}, static_cast<std::uint32_t>(plan.groups.size()));
    if (inserted) plan.groups.push_back(PlannedGroup{.general = stage(kind, name), .name = name});
    return it->second;
  };
  std::vector<bool> signature_used(s.local_signatures().size(), false);
  auto use = [&](SbtRegionKind region, std::uint32_t entry_index, std::uint32_t ray) {
    if (ray != no_index) plan.max_payload_size = std::max(plan.max_payload_size, s.ray(RayId<>(ray)).payload_size);
    if (entry_index == no_index) return;
    const Entry& e = entry(entry_index);
    auto& max = plan.max_root_arguments_size[static_cast<std::uint32_t>(region)];
    max = std::max(max, e.arguments_size);
    if (e.local_signature != no_index) signature_used[e.local_signature] = true;
  };
  for (std::uint32_t i : raygen) {
    const std::uint32_t g = general(ShaderStage::raygen, s.entries().raygen_shaders()[entry(i).shader]);
    out.m_records[0].push_back(SbtRecord{g, i, no_index, no_index, no_index});
    use(SbtRegionKind::raygen, i, no_index);
  }
  for (std::uint32_t r = 0; r < rays; ++r) {
    const std::string& miss = s.ray(RayId<>(r)).desc.miss;
    const std::uint32_t g = miss.empty() ? no_index : general(ShaderStage::miss, miss);
    out.m_records[1].push_back(SbtRecord{g, miss_of_ray[r], r, no_index, no_index});
    use(SbtRegionKind::miss, miss_of_ray[r], g == no_index ? no_index : r);
  }
  std::vector<std::uint32_t> group_of(s.hit_groups().size(), no_index);
  for (const SbtRecord& record : out.m_records[2]) {
    group_of[entry(record.entry).hit_group] = 0;
    use(SbtRegionKind::hit, record.entry, record.ray);
  }
  for (std::uint32_t h = 0; h < group_of.size(); ++h) {
    if (group_of[h] == no_index) continue;
    const HitGroup& hg = s.hit_groups().entities()[h];
    group_of[h] = static_cast<std::uint32_t>(plan.groups.size());
    plan.groups.push_back(PlannedGroup{
        .type = hg.desc.kind == HitGroupKind::triangles ? GroupType::triangles_hit : GroupType::procedural_hit,
        .closest_hit = stage(ShaderStage::closest_hit, hg.desc.closest_hit),
        .any_hit = stage(ShaderStage::any_hit, hg.desc.any_hit),
        .intersection = stage(ShaderStage::intersection, hg.desc.intersection, hg.desc.any_hit),
        .name = s.hit_groups().name(h), .hit_group = HitGroupId(h), .attribute_size = hg.attribute_size});
    plan.max_attribute_size = std::max(plan.max_attribute_size, hg.attribute_size);
  }
  for (SbtRecord& record : out.m_records[2]) record.group = group_of[entry(record.entry).hit_group];
  // Callable records: one per registered callable, in callable-index order.
  for (std::uint32_t c = 0; c < s.callables().size(); ++c) {
    const std::uint32_t g = general(ShaderStage::callable, s.callables().entities()[c].desc.shader);
    out.m_records[3].push_back(SbtRecord{g, callable_entry[c], no_index, no_index, no_index});
    use(SbtRegionKind::callable, callable_entry[c], no_index);
  }
  for (std::uint32_t i = 0; i < signature_used.size(); ++i) {
    if (signature_used[i]) plan.local_signatures.push_back(LocalSignatureId<>(i));
  }
  const auto all = s.entries().all();
  out.m_entries.assign(all.begin(), all.end());
  const auto data = s.entries().data();
  out.m_data.assign(data.begin(), data.end());
  fields();  // after the stages (it gives the fields' theirs source) and the outputs' bindings
}

PROCEDURAY_DECL void PlanBuilder::declarations() {
  // Every name the declarations will hold, checked once more with the pipeline's global signature
  // and the struct type names (registration saw neither): a clash here would surface as a glslang
  // error on a line of generated code.
  std::vector<GlslName> names = s.glsl_names();  // rays, layers, callables
  if (out.m_global) {
    for (GlslName& n : Entities::signature_glsl_names(*out.m_global)) names.push_back(std::move(n));
  }
  std::vector<const TypeOps*> types;
  auto type = [&](const TypeOps* t) {
    if (t == nullptr || t->kind != TypeKind::structure || std::find(types.begin(), types.end(), t) != types.end()) return;
    types.push_back(t);
    names.push_back({std::string(t->glsl_name), "struct " + std::string(t->glsl_name)});
  };
  for (const SceneConstant& c : out.m_constants) names.push_back({c.name, quote_origin(c.define ? "define" : "constant", c.name)});
  for (const TypeOps* t : s.vocabulary()) type(t);
  for (const Ray& r : s.rays().entities()) type(r.payload_glsl);
  for (const HitGroup& g : s.hit_groups().entities()) type(g.attribute_glsl);
  for (const LocalSignature& l : s.local_signatures().entities()) type(l.arguments_glsl);
  for (const Callable& c : s.callables().entities()) type(c.data_glsl);
  if (out.m_global) {
    for (const Binding& b : out.m_global->bindings) type(b.type);
    type(out.m_global->push_constants.type);
  }
  check_glsl_names(op, {}, names);
  const std::string common = detail::common_declarations(s, out);
  for (PlannedStage& stage : out.m_pipeline.stages) {
    stage.declarations = common + detail::stage_declarations(s, out, stage.stage, stage.shader);
  }
}

PROCEDURAY_DECL Plan detail::compile_core(const SceneCore& scene) {
  PlanBuilder b(scene);
  b.instances();
  b.sort_entries();
  b.hit_records();
  b.meshes();
  b.pipeline();
  b.declarations();
  return std::move(b.out);
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
