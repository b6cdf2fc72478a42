// The GLSL declarations each shader of a scene needs, derived by compile(scene): nothing about
// payloads, attributes, records or bindings is written twice, and no device is involved, so a
// build step can write them to files (tools/glsl_for) as well as the renderer at run time.
//
//   const proceduray::Plan plan = proceduray::compile(scene);
//   std::string preamble = proceduray::glsl_for(plan, proceduray::ShaderStage::closest_hit, "shade.rchit");
//   std::string names = proceduray::glsl_summary(preamble);   // one line per name, no struct bodies
//
// What a shader gets (names are the convention the shaders use):
//   every stage   the structs of every registered type the scene uses; per ray type
//                 `const uint <ray>_ray`, `<ray>_flags` and `<ray>_mask` (its RayDesc), and
//                 `ray_count`; `layer_<name>` per layer; `<id>_callable` per callable; the
//                 `<geometry>_aabb_min`/`_max` of every procedural geometry (aabb_glsl.hpp); each
//                 named binding of the global signature (acceleration structure, rgba8 storage
//                 image, typed uniform, or a readonly storage buffer of T[] read as `<name>.data[i]`),
//                 and its named push constant block (`<name>.member`); the per-pixel output
//                 helpers output_t/normal/ids/steps/flags (outputs_glsl.hpp: empty macros for
//                 outputs not asked for), and output_hit(n) in closest-hit and any-hit stages;
//                 for each MeshRef<V> in root arguments, vertex(m, i), triangle_indices(m, prim) and
//                 interpolate(m, prim, barycentrics) (shader/mesh_ref.hpp)
//   tracing stages (raygen, miss, closest hit: the ones Vulkan lets trace)
//                 `rayPayloadEXT <Payload> <ray>` for every ray type, at location = ray index,
//                 and per ray type (when the global signature names an acceleration structure)
//                   void      trace_<ray>(vec3 origin, float tmin, vec3 direction, float tmax)
//                   <Payload> trace_<ray>(vec3 origin, float tmin, vec3 direction, float tmax, <Payload> p)
//                 which fill flags, mask, SBT offset and stride, miss index and payload location
//                 from the ray's declaration; the second copies p in and returns what the shaders
//                 left. A closest-hit shader has an outgoing payload of its own ray type too, so a
//                 reflection needs no save and restore of `payload`.
//   calling stages (raygen, miss, closest hit, callable)
//                 `callableDataEXT <Data> <id>_data` per callable, at location = its index, and
//                   <Data> <id>_call(<Data> d)   (copies d in, executeCallableEXT, returns the data)
//   miss          `rayPayloadInEXT <Payload> payload` of the ray types it is the miss shader of
//   closest hit   `rayPayloadInEXT <Payload> payload` of the rays whose records use it, the
//                 group's `hitAttributeEXT <Attributes> hit`, the entries' `arguments` block (root arguments)
//   any hit       payload, hit and arguments as closest hit; no tracing, no callables
//   intersection  `hitAttributeEXT <Attributes> hit` and the entries' `arguments` block (root arguments)
//   callable      `callableDataInEXT <Data> call` of the callables it implements and their
//                 `arguments` block (root arguments); the other callables as above
// Incoming payloads and callable data sit at location ray_count (callable_count): past every
// outgoing one, so the two never overlap. A shader calling trace_<ray> for a ray the scene does
// not declare fails to compile, and the renderer's message names the ray and the declared ones.
// compile() throws SceneError when one shader is used in ways that need two different types
// (two payloads, attributes or record types), naming them: split the shader or unify the types.
// Every block comes from shader/glsl_codegen.hpp, the one GLSL emitter.
#pragma once

#include <proceduray/config.hpp>

#include "proceduray/scene/aabb_glsl.hpp"
#include "proceduray/scene/glsl_names.hpp"
#include "proceduray/scene/outputs_glsl.hpp"
#include "proceduray/scene/plan.hpp"
#include "proceduray/scene/scene.hpp"
#include "proceduray/shader/glsl_codegen.hpp"
#include "proceduray/shader/mesh_ref.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray {

namespace detail {

using proceduray::glsl_identifier;  // glsl_names.hpp

/// The one type a shader's uses agree on, or nullptr; throws when they disagree.
PROCEDURAY_DECL const TypeOps* one_type(const std::vector<const TypeOps*>& types, std::string_view shader, const char* what);

PROCEDURAY_DECL std::string binding_glsl(const Binding& b);

}  // namespace detail

namespace detail {

/// What every stage gets: the structs of every registered type, ray, layer and callable
/// constants, the named bindings and the push constant block.
PROCEDURAY_DECL std::string common_declarations(const detail::SceneCore& scene, const Plan& plan);

/// The record block of a shader whose records carry `types` (one type, or none).
PROCEDURAY_DECL std::string record_block(const std::vector<const TypeOps*>& types, std::string_view shader);

/// Outgoing callable data of every callable but `skip` (the one a callable shader receives), and
/// `<id>_call(d)` for each.
PROCEDURAY_DECL std::string callable_data(const detail::SceneCore& scene, std::uint32_t skip);

/// The name of the acceleration structure the trace functions trace: the global signature's
/// first named one, or "" (then there are no trace functions).
PROCEDURAY_DECL std::string trace_target(const Plan& plan);

/// What a tracing stage (raygen, miss, closest hit) gets: every ray's outgoing payload, at
/// location = ray index, and its two trace functions.
PROCEDURAY_DECL std::string tracing_declarations(const detail::SceneCore& scene, const Plan& plan);

/// The root arguments type of a record, or nullptr.
PROCEDURAY_DECL const TypeOps* arguments_type(const detail::SceneCore& scene, const Plan& plan, const SbtRecord& record);

/// Payload, attributes, record and outgoing payloads of a hit-group stage.
PROCEDURAY_DECL std::string hit_declarations(const detail::SceneCore& scene, const Plan& plan, ShaderStage stage, std::string_view shader);

/// What `shader` as `stage` gets after the common declarations (see the top of this header);
/// compile() prepends common_declarations, the same for every stage, computed once.
PROCEDURAY_DECL std::string stage_declarations(const detail::SceneCore& scene, const Plan& plan, ShaderStage stage, std::string_view shader);

}  // namespace detail

/// The declarations compile() derived for `shader` as `stage`; throws UnknownIdError when the
/// plan has no such stage (a shader no entry uses, or the wrong stage).
PROCEDURAY_DECL const std::string& glsl_for(const Plan& plan, ShaderStage stage, std::string_view shader);

/// The names a shader's declarations give it, one line each: a struct as `struct T`, a block as
/// its header and instance name, a function as its signature, constants, variables and macros as
/// written. What `glsl_for` tools print (glsl_files_main --names), for a newcomer asking "what
/// can this shader call?".
PROCEDURAY_DECL std::string glsl_summary(std::string_view declarations);

}  // namespace proceduray

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

PROCEDURAY_DECL std::string tracing_declarations(const detail::SceneCore& scene, const Plan& plan) {
  std::string out;
  const std::string tlas = trace_target(plan);
  for (std::uint32_t r = 0; r < scene.rays().size(); ++r) {
    const std::string name = glsl_identifier(scene.rays().name(r));
    const TypeOps& payload = *scene.ray(RayId<>(r)).payload_glsl;
    out += glsl_ray_payload(r, payload, name);
    if (tlas.empty()) continue;
    const std::string type(payload.glsl_name), params = "vec3 origin, float tmin, vec3 direction, float tmax";
    // traceRayEXT(tlas, flags, mask, sbt offset, sbt stride, miss index, ..., payload location)
    out += "void trace_" + name + "(" + params + ") { traceRayEXT(" + tlas + ", " + name + "_flags, " + name +
           "_mask, " + name + "_ray, ray_count, " + name + "_ray, origin, tmin, direction, tmax, " +
           std::to_string(r) + "); }\n";
    out += type + " trace_" + name + "(" + params + ", " + type + " p) { " + name + " = p; trace_" + name +
           "(origin, tmin, direction, tmax); return " + name + "; }\n";
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
  if (stage == ShaderStage::closest_hit) out += tracing_declarations(scene, plan) + callable_data(scene, no_index);
  return out;
}

PROCEDURAY_DECL std::string stage_declarations(const detail::SceneCore& scene, const Plan& plan, ShaderStage stage, std::string_view shader) {
  std::string out;
  const auto rays = scene.rays().size();
  std::vector<const TypeOps*> payloads, records;
  std::uint32_t location = no_index;
  switch (stage) {
    case ShaderStage::raygen:
      out += tracing_declarations(scene, plan);
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
      return out + record_block(records, shader) + tracing_declarations(scene, plan) + callable_data(scene, no_index);
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
