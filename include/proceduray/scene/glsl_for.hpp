// The GLSL declarations each shader of a scene needs, derived by compile(scene): nothing about
// payloads, attributes, records or bindings is written twice, and no device is involved, so a
// build step can write them to files (tools/glsl_for) as well as the renderer at run time.
//
//   const proceduray::Plan plan = proceduray::compile(scene);
//   std::string preamble = proceduray::glsl_for(plan, proceduray::ShaderStage::closest_hit, "shade.rchit");
//
// What a shader gets (names are the convention the shaders use):
//   every stage   the structs of every registered type the scene uses; per ray type
//                 `const uint <ray>_ray`, `<ray>_flags` and `<ray>_mask` (its RayDesc), and
//                 `ray_count`; `layer_<name>` per layer; `<id>_callable` per callable; each
//                 named binding of the global signature (acceleration structure, rgba8 storage
//                 image, typed uniform, or a readonly storage buffer of T[] read as `<name>.data[i]`),
//                 and its named push constant block (`<name>.member`); the per-pixel output
//                 helpers output_t/normal/ids/steps/flags (outputs_glsl.hpp: empty macros for
//                 outputs not asked for), and output_hit(n) in closest-hit and any-hit stages
//   raygen        `rayPayloadEXT <Payload> <ray>` for every ray type, at location = ray index,
//                 and `callableDataEXT <Data> <id>_call` per callable, at location = its index
//   miss          `rayPayloadInEXT <Payload> payload` of the ray types it is the miss shader of,
//                 and the callables' data
//   closest hit   `rayPayloadInEXT <Payload> payload` of the rays whose records use it, the
//                 group's `hitAttributeEXT <Attributes> hit`, the entries' `arguments` block (root arguments),
//                 `rayPayloadEXT` for the other ray types (to trace shadow rays, say), and the
//                 callables' data
//   any hit       as closest hit, without outgoing payloads or callable data
//   intersection  `hitAttributeEXT <Attributes> hit` and the entries' `arguments` block (root arguments)
//   callable      `callableDataInEXT <Data> call` of the callables it implements, their
//                 `arguments` block (root arguments), and the other callables' data
// compile() throws SceneError when one shader is used in ways that need two different types
// (two payloads, attributes or record types), naming them: split the shader or unify the types.
// Every block comes from shader/glsl_codegen.hpp, the one GLSL emitter.
#pragma once

#include "proceduray/scene/glsl_names.hpp"
#include "proceduray/scene/outputs_glsl.hpp"
#include "proceduray/scene/plan.hpp"
#include "proceduray/scene/scene.hpp"
#include "proceduray/shader/glsl_codegen.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray {

namespace detail {

using proceduray::glsl_identifier;  // glsl_names.hpp

/// The one type a shader's uses agree on, or nullptr; throws when they disagree.
inline const TypeOps* one_type(const std::vector<const TypeOps*>& types, std::string_view shader, const char* what) {
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

inline std::string binding_glsl(const Binding& b) {
  const std::string name = glsl_identifier(b.name);
  const std::string where = "layout(set = " + std::to_string(b.set) + ", binding = " + std::to_string(b.binding);
  switch (b.kind) {
    case BindingKind::acceleration_structure: return where + ") uniform accelerationStructureEXT " + name + ";\n";
    case BindingKind::storage_image: return where + ", rgba8) uniform image2D " + name + ";\n";
    case BindingKind::output_image: return {};  // declared with its format by glsl_outputs
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

}  // namespace detail

namespace detail {

/// What every stage gets: the structs of every registered type, ray, layer and callable
/// constants, the named bindings and the push constant block.
inline std::string common_declarations(const Scene& scene, const Plan& plan) {
  std::vector<const TypeOps*> roots;  // a fixed order: payloads, attributes, records, callables, bindings
  auto add_root = [&](const TypeOps* t) {
    if (t != nullptr && std::find(roots.begin(), roots.end(), t) == roots.end()) roots.push_back(t);
  };
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
  for (std::uint32_t r = 0; r < scene.rays().size(); ++r) {
    const std::string name = glsl_identifier(scene.rays().name(r));
    const RayDesc& desc = scene.ray(RayId<>(r)).desc;
    out += glsl_const(name + "_ray", r);
    out += glsl_const(name + "_flags", static_cast<std::uint32_t>(desc.flags));
    out += glsl_const(name + "_mask", std::uint32_t{desc.cull_mask});
  }
  out += glsl_const("ray_count", scene.rays().size());
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
  return out + glsl_outputs(plan.outputs());
}

/// The record block of a shader whose records carry `types` (one type, or none).
inline std::string record_block(const std::vector<const TypeOps*>& types, std::string_view shader) {
  const TypeOps* t = one_type(types, shader, "root arguments");
  return t == nullptr ? std::string() : glsl_root_arguments(*t, "arguments");
}

/// Outgoing callable data of every callable but `skip` (the one a callable shader receives).
inline std::string callable_data(const Scene& scene, std::uint32_t skip) {
  std::string text;
  for (std::uint32_t c = 0; c < scene.callables().size(); ++c) {
    if (c == skip) continue;
    text += glsl_callable_data(c, *scene.callable(CallableId<>(c)).data_glsl,
                               glsl_identifier(scene.callables().name(c)) + "_call");
  }
  return text;
}

/// The root arguments type of a record, or nullptr.
inline const TypeOps* arguments_type(const Scene& scene, const Plan& plan, const SbtRecord& record) {
  const Entry* e = plan.entry(record);
  if (e == nullptr || e->local_signature == no_index) return nullptr;
  return scene.local_signature(LocalSignatureId<>(e->local_signature)).arguments_glsl;
}

/// Payload, attributes, record and outgoing payloads of a hit-group stage.
inline std::string hit_declarations(const Scene& scene, const Plan& plan, ShaderStage stage, std::string_view shader) {
  std::vector<const TypeOps*> payloads, attributes, records;
  std::uint32_t location = no_index;
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
    location = std::min(location, rec.ray);
  }
  std::string out;
  // An intersection shader sees no payload, so its uses may differ in payload type.
  if (stage != ShaderStage::intersection) {
    if (const TypeOps* p = one_type(payloads, shader, "payload"); p != nullptr) {
      out += glsl_ray_payload(location, *p, "payload", true);
    }
  }
  if (const TypeOps* a = one_type(attributes, shader, "hit attribute"); a != nullptr) out += glsl_hit_attribute(*a, "hit");
  out += record_block(records, shader);
  if (stage != ShaderStage::intersection) out += glsl_output_hit(plan.outputs());
  if (stage == ShaderStage::closest_hit) {
    for (std::uint32_t r = 0; r < scene.rays().size(); ++r) {
      if (r != location) out += glsl_ray_payload(r, *scene.ray(RayId<>(r)).payload_glsl, glsl_identifier(scene.rays().name(r)));
    }
    out += callable_data(scene, no_index);
  }
  return out;
}

/// What `shader` as `stage` gets after the common declarations (see the top of this header);
/// compile() prepends common_declarations, the same for every stage, computed once.
inline std::string stage_declarations(const Scene& scene, const Plan& plan, ShaderStage stage, std::string_view shader) {
  std::string out;
  const auto rays = scene.rays().size();
  std::vector<const TypeOps*> payloads, records;
  std::uint32_t location = no_index;
  switch (stage) {
    case ShaderStage::raygen:
      for (std::uint32_t r = 0; r < rays; ++r) {
        out += glsl_ray_payload(r, *scene.ray(RayId<>(r)).payload_glsl, glsl_identifier(scene.rays().name(r)));
      }
      for (const SbtRecord& rec : plan.records(SbtRegionKind::raygen)) {
        if (plan.pipeline().groups[rec.group].name == shader) records.push_back(arguments_type(scene, plan, rec));
      }
      return out + record_block(records, shader) + callable_data(scene, no_index);
    case ShaderStage::miss:
      for (const SbtRecord& rec : plan.records(SbtRegionKind::miss)) {
        if (scene.ray(RayId<>(rec.ray)).desc.miss != shader) continue;
        payloads.push_back(scene.ray(RayId<>(rec.ray)).payload_glsl);
        records.push_back(arguments_type(scene, plan, rec));
        location = std::min(location, rec.ray);
      }
      if (const TypeOps* p = one_type(payloads, shader, "payload"); p != nullptr) {
        out += glsl_ray_payload(location, *p, "payload", true);
      }
      return out + record_block(records, shader) + callable_data(scene, no_index);
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
        out += glsl_callable_data(location, *d, "call", true);
      }
      return out + record_block(records, shader) + callable_data(scene, location);
    }
  }
  return out;
}

}  // namespace detail

/// The declarations compile() derived for `shader` as `stage`; throws UnknownIdError when the
/// plan has no such stage (a shader no entry uses, or the wrong stage).
inline const std::string& glsl_for(const Plan& plan, ShaderStage stage, std::string_view shader) {
  return plan.declarations(stage, shader);
}

}  // namespace proceduray
