// The bodies of proceduray/scene/glsl_for.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/glsl_for.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::detail {

PROCEDURAY_DECL const TypeOps* one_type(const std::vector<const TypeOps*>& types, std::string_view shader, const char* what) {
  const TypeOps* found = nullptr;
  for (const TypeOps* t : types) {
    if (t == nullptr) continue;
    if (found != nullptr && found != t) {
      throw SceneError("compile: shader \"" + std::string(shader) + "\" is used with two " + what + " types, " +
                       std::string(found->glsl_name) + " and " + std::string(t->glsl_name) +
                       "; give each use its own shader or one type");
    }
    found = t;
  }
  return found;
}

PROCEDURAY_DECL std::string binding_glsl(const Binding& b) {
  const std::string name = glsl_identifier(b.name);
  const std::string where = "layout(set = " + std::to_string(b.set) + ", binding = " + std::to_string(b.binding);
  switch (b.kind) {
    case BindingKind::acceleration_structure: return where + ") uniform accelerationStructureEXT " + name + ";\n";
    case BindingKind::storage_image: return where + ", rgba8) uniform image2D " + name + ";\n";
    case BindingKind::output_image: return {};  // declared with its format by glsl_outputs
    case BindingKind::sampled_image:
      return where + ") uniform " + (b.cube ? "samplerCube " : "sampler2D ") + name +
             (b.count > 1 ? "[" + std::to_string(b.count) + "]" : std::string()) + ";\n";
    case BindingKind::uniform_buffer:
    case BindingKind::storage_buffer:
      if (b.type == nullptr) {
        throw SceneError("compile: binding \"" + b.name + "\" (set " + std::to_string(b.set) + ", binding " +
                         std::to_string(b.binding) + ") is named but has no type; declare it with a UniformSlot<T>");
      }
      return b.kind == BindingKind::uniform_buffer ? glsl_uniform(*b.type, b.set, b.binding, name)
                                                   : glsl_storage_buffer(*b.type, b.set, b.binding, name);
  }
  return {};
}

PROCEDURAY_DECL std::string common_declarations(const detail::SceneCore& scene, const Plan& plan) {
  // The interface's alternatives, in category order, are the vocabulary every stage declares;
  // what the scene registered is among them (Scene<Interface> refuses the rest at compile time).
  std::vector<const TypeOps*> roots;
  auto add_root = [&](const TypeOps* t) {
    if (t != nullptr && std::find(roots.begin(), roots.end(), t) == roots.end()) roots.push_back(t);
  };
  for (const TypeOps* t : scene.vocabulary()) add_root(t);
  for (const Ray& r : scene.rays().entities()) add_root(r.payload_glsl);
  for (const HitGroup& g : scene.hit_groups().entities()) add_root(g.attribute_glsl);
  for (const LocalSignature& l : scene.local_signatures().entities()) add_root(l.arguments_glsl);
  for (const Callable& c : scene.callables().entities()) add_root(c.data_glsl);
  const GlobalSignatureDesc* global = plan.global_signature();
  if (global != nullptr) {
    for (const Binding& b : global->bindings) add_root(b.type);
    add_root(global->push_constants.type);
  }
  std::string out = glsl_declarations(std::span<const TypeOps* const>(roots), true);
  std::vector<const TypeOps*> meshes;  // MeshRef members of root arguments: their accessors
  for (const LocalSignature& l : scene.local_signatures().entities()) {
    for (std::size_t i = 0; l.arguments_glsl != nullptr && i < l.arguments_glsl->field_count; ++i) {
      const TypeOps* t = l.arguments_glsl->fields[i].type;
      if (t->mesh_vertex != nullptr && std::find(meshes.begin(), meshes.end(), t) == meshes.end()) meshes.push_back(t);
    }
  }
  for (const TypeOps* m : meshes) out += glsl_mesh_functions(*m);
  for (std::uint32_t r = 0; r < scene.rays().size(); ++r) {
    const std::string name = glsl_identifier(scene.rays().name(r));
    const RayDesc& desc = scene.ray(RayId<>(r)).desc;
    out += glsl_const(name + "_ray", r);
    out += glsl_const(name + "_flags", static_cast<std::uint32_t>(desc.flags));
    out += glsl_const(name + "_mask", std::uint32_t{desc.cull_mask});
  }
  out += glsl_const("ray_count", scene.rays().size());
  for (const SceneConstant& c : plan.constants()) out += glsl_constant(c);
  const auto layers = scene.layers().names();
  for (std::uint32_t l = 0; l < layers.size(); ++l) out += glsl_const("layer_" + glsl_identifier(layers[l]), 1u << l);
  for (std::uint32_t c = 0; c < scene.callables().size(); ++c) {
    out += glsl_const(glsl_identifier(scene.callables().name(c)) + "_callable", c);
  }
  if (global != nullptr) {
    for (const Binding& b : global->bindings) {
      if (!b.name.empty()) out += binding_glsl(b);
    }
    const PushConstantBlock& push = global->push_constants;
    if (push.type != nullptr && !push.name.empty()) out += glsl_push_constant(*push.type, glsl_identifier(push.name));
  }
  return out + glsl_aabb_consts(scene) + glsl_outputs(plan.outputs());
}

PROCEDURAY_DECL std::string record_block(const std::vector<const TypeOps*>& types, std::string_view shader) {
  const TypeOps* t = one_type(types, shader, "root arguments");
  return t == nullptr ? std::string() : glsl_root_arguments(*t, "arguments");
}

PROCEDURAY_DECL std::string callable_data(const detail::SceneCore& scene, std::uint32_t skip) {
  std::string text;
  for (std::uint32_t c = 0; c < scene.callables().size(); ++c) {
    if (c == skip) continue;
    const std::string name = glsl_identifier(scene.callables().name(c));
    const std::string type(scene.callable(CallableId<>(c)).data_glsl->glsl_name);
    text += glsl_callable_data(c, *scene.callable(CallableId<>(c)).data_glsl, name + "_data");
    text += type + " " + name + "_call(" + type + " d) { " + name + "_data = d; executeCallableEXT(" + name +
            "_callable, " + std::to_string(c) + "); return " + name + "_data; }\n";
  }
  return text;
}

PROCEDURAY_DECL std::string trace_target(const Plan& plan) {
  const GlobalSignatureDesc* global = plan.global_signature();
  if (global == nullptr) return {};
  for (const Binding& b : global->bindings) {
    if (b.kind == BindingKind::acceleration_structure && !b.name.empty()) return glsl_identifier(b.name);
  }
  return {};
}

PROCEDURAY_DECL std::string depth_counter(const Plan& plan, bool raygen) {
  if (plan.depth_binding() == no_index) return {};
  // The nesting of the running shader, per pixel: raygen's traces are level 1; a nested trace
  // reads its level, refuses past the pipeline's depth, and puts it back when the trace returns.
  const std::string image = "proceduray_depth_image", at = "ivec2(gl_LaunchIDEXT.xy)";
  std::string out = "layout(set = 0, binding = " + std::to_string(plan.depth_binding()) + ", r32ui) uniform coherent "
                    "uimage2D " + image + ";\nconst uint proceduray_max_depth = " +
                    std::to_string(plan.pipeline().max_recursion_depth) + "u;\n";
  if (raygen) {
    return out + "bool proceduray_enter() { imageStore(" + image + ", " + at + ", uvec4(1u)); return true; }\n"
                 "void proceduray_leave() {}\n";
  }
  return out + "uint proceduray_level = 0u;\n"
               "bool proceduray_enter() {\n"
               "  proceduray_level = imageLoad(" + image + ", " + at + ").x;\n"
               "  if (proceduray_level >= proceduray_max_depth) { output_flags(output_flag_depth); return false; }\n"
               "  imageStore(" + image + ", " + at + ", uvec4(proceduray_level + 1u));\n"
               "  return true;\n"
               "}\n"
               "void proceduray_leave() { imageStore(" + image + ", " + at + ", uvec4(proceduray_level)); }\n";
}

PROCEDURAY_DECL std::string tracing_declarations(const detail::SceneCore& scene, const Plan& plan, bool raygen) {
  std::string out;
  const std::string tlas = trace_target(plan);
  if (!tlas.empty()) out += depth_counter(plan, raygen);
  for (std::uint32_t r = 0; r < scene.rays().size(); ++r) {
    const std::string name = glsl_identifier(scene.rays().name(r));
    const TypeOps& payload = *scene.ray(RayId<>(r)).payload_glsl;
    out += glsl_ray_payload(r, payload, name);
    if (tlas.empty()) continue;
    const std::string type(payload.glsl_name), params = "vec3 origin, float tmin, vec3 direction, float tmax";
    // traceRayEXT(tlas, flags, mask, sbt offset, sbt stride, miss index, ..., payload location)
    std::string trace = "traceRayEXT(" + tlas + ", " + name + "_flags, " + name + "_mask, " + name +
                        "_ray, ray_count, " + name + "_ray, origin, tmin, direction, tmax, " + std::to_string(r) + ");";
    // Past the declared depth the trace is skipped: the payload keeps what it held (a miss
    // without a miss shader) and the pixel's flags output gets output_flag_depth.
    if (plan.depth_binding() != no_index) trace = "if (proceduray_enter()) { " + trace + " proceduray_leave(); }";
    // Without a miss shader a miss leaves the payload as it was: only the form that takes the
    // payload is generated, so a miss returns what the caller passed, never uninitialised memory.
    if (!scene.ray(RayId<>(r)).desc.miss.empty()) out += "void trace_" + name + "(" + params + ") { " + trace + " }\n";
    out += type + " trace_" + name + "(" + params + ", " + type + " p) { " + name + " = p; " + trace + " return " +
           name + "; }\n";
  }
  return out;
}

PROCEDURAY_DECL const TypeOps* arguments_type(const detail::SceneCore& scene, const Plan& plan, const SbtRecord& record) {
  const Entry* e = plan.entry(record);
  if (e == nullptr || e->local_signature == no_index) return nullptr;
  return scene.local_signature(LocalSignatureId<>(e->local_signature)).arguments_glsl;
}

PROCEDURAY_DECL std::string hit_declarations(const detail::SceneCore& scene, const Plan& plan, ShaderStage stage, std::string_view shader) {
  std::vector<const TypeOps*> payloads, attributes, records;
  for (const SbtRecord& rec : plan.records(SbtRegionKind::hit)) {
    if (rec.group == no_index) continue;
    const HitGroup& group = scene.hit_group(plan.pipeline().groups[rec.group].hit_group);
    const std::string& uses = stage == ShaderStage::closest_hit ? group.desc.closest_hit
                              : stage == ShaderStage::any_hit   ? group.desc.any_hit
                                                                : group.desc.intersection;
    if (uses != shader) continue;
    attributes.push_back(group.attribute_glsl);
    records.push_back(arguments_type(scene, plan, rec));
    payloads.push_back(scene.ray(RayId<>(rec.ray)).payload_glsl);
  }
  std::string out;
  // An intersection shader sees no payload, so its uses may differ in payload type.
  if (stage != ShaderStage::intersection) {
    if (const TypeOps* p = one_type(payloads, shader, "payload"); p != nullptr) {
      out += glsl_ray_payload(scene.rays().size(), *p, "payload", true);
    }
  }
  if (const TypeOps* a = one_type(attributes, shader, "hit attribute"); a != nullptr) out += glsl_hit_attribute(*a, "hit");
  out += record_block(records, shader);
  if (stage != ShaderStage::intersection) out += glsl_output_hit(plan.outputs());
  if (stage == ShaderStage::closest_hit) out += tracing_declarations(scene, plan, false) + callable_data(scene, no_index);
  return out;
}

PROCEDURAY_DECL std::string stage_declarations(const detail::SceneCore& scene, const Plan& plan, ShaderStage stage, std::string_view shader) {
  std::string out;
  const auto rays = scene.rays().size();
  std::vector<const TypeOps*> payloads, records;
  std::uint32_t location = no_index;
  switch (stage) {
    case ShaderStage::raygen:
      out += tracing_declarations(scene, plan, true);
      for (const SbtRecord& rec : plan.records(SbtRegionKind::raygen)) {
        if (plan.pipeline().groups[rec.group].name == shader) records.push_back(arguments_type(scene, plan, rec));
      }
      return out + record_block(records, shader) + callable_data(scene, no_index);
    case ShaderStage::miss:
      for (const SbtRecord& rec : plan.records(SbtRegionKind::miss)) {
        if (scene.ray(RayId<>(rec.ray)).desc.miss != shader) continue;
        payloads.push_back(scene.ray(RayId<>(rec.ray)).payload_glsl);
        records.push_back(arguments_type(scene, plan, rec));
      }
      if (const TypeOps* p = one_type(payloads, shader, "payload"); p != nullptr) {
        out += glsl_ray_payload(rays, *p, "payload", true);
      }
      return out + record_block(records, shader) + tracing_declarations(scene, plan, false) + callable_data(scene, no_index);
    case ShaderStage::closest_hit:
    case ShaderStage::any_hit:
    case ShaderStage::intersection: return out + hit_declarations(scene, plan, stage, shader);
    case ShaderStage::callable: {
      const auto list = plan.records(SbtRegionKind::callable);
      for (std::uint32_t c = 0; c < list.size(); ++c) {
        if (scene.callable(CallableId<>(c)).desc.shader != shader) continue;
        payloads.push_back(scene.callable(CallableId<>(c)).data_glsl);
        records.push_back(arguments_type(scene, plan, list[c]));
        location = std::min(location, c);
      }
      if (const TypeOps* d = one_type(payloads, shader, "callable data"); d != nullptr) {
        out += glsl_callable_data(static_cast<std::uint32_t>(list.size()), *d, "call", true);
      }
      return out + record_block(records, shader) + callable_data(scene, location);
    }
    case ShaderStage::compute: return out;  // no scene holds one: nothing of the scene to declare
  }
  return out;
}

}  // namespace proceduray::detail

namespace proceduray {

PROCEDURAY_DECL const std::string& glsl_for(const Plan& plan, ShaderStage stage, std::string_view shader) {
  return plan.declarations(stage, shader);
}

PROCEDURAY_DECL std::string glsl_summary(std::string_view declarations) {
  std::string out, block;  // block: the header of the struct or block being skipped
  std::size_t at = 0;
  while (at < declarations.size()) {
    std::size_t end = declarations.find('\n', at);
    if (end == std::string_view::npos) end = declarations.size();
    std::string_view line = declarations.substr(at, end - at);
    at = end + 1;
    if (!block.empty()) {  // inside a struct or block: only its closing line matters
      if (!line.starts_with("}")) continue;
      std::string_view instance = line.substr(1);
      while (!instance.empty() && (instance.front() == ' ')) instance.remove_prefix(1);
      if (instance.ends_with(";")) instance.remove_suffix(1);
      out += block + (instance.empty() ? "" : " " + std::string(instance)) + "\n";
      block.clear();
      continue;
    }
    if (line.empty() || line.starts_with("#if") || line.starts_with("#endif") || line.starts_with("#extension") ||
        line.starts_with("#define PROCEDURAY_")) {
      continue;
    }
    if (line.ends_with("{")) {  // a struct or block header
      std::string_view head = line.substr(0, line.size() - 1);
      while (head.ends_with(" ")) head.remove_suffix(1);
      block = head;
      continue;
    }
    if (const std::size_t body = line.find(") { "); body != std::string_view::npos) {  // a one-line function
      out += std::string(line.substr(0, body + 1)) + "\n";
      continue;
    }
    out += std::string(line) + "\n";
  }
  return out;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
