// The GLSL declarations each shader of a built table needs, derived from the scene: nothing
// about payloads, attributes, records or bindings is written twice.
//
//   std::string preamble = proceduray::glsl_for(sbt, ShaderStage::closest_hit, "shade.rchit");
//
// What a shader gets (names are the convention the shaders use):
//   every stage   the structs of every registered type the scene uses; per ray type
//                 `const uint <ray>_ray`, `<ray>_flags` and `<ray>_mask` (its RayDesc), and
//                 `ray_count`; `layer_<name>` per layer; `<id>_callable` per callable; each
//                 named binding of the global signature (acceleration structure, rgba8 storage
//                 image, typed uniform, or a readonly storage buffer of T[] read as `<name>.data[i]`),
//                 and its named push constant block (`<name>.member`)
//   raygen        `rayPayloadEXT <Payload> <ray>` for every ray type, at location = ray index,
//                 and `callableDataEXT <Data> <id>_call` per callable, at location = its index
//   miss          `rayPayloadInEXT <Payload> payload` of the ray types it is the miss shader of,
//                 and the callables' data
//   closest hit   `rayPayloadInEXT <Payload> payload` of the rays whose records use it, the
//                 group's `hitAttributeEXT <Attributes> hit`, the entries' `record` block,
//                 `rayPayloadEXT` for the other ray types (to trace shadow rays, say), and the
//                 callables' data
//   any hit       as closest hit, without outgoing payloads or callable data
//   intersection  `hitAttributeEXT <Attributes> hit` and the entries' `record` block
//   callable      `callableDataInEXT <Data> call` of the callables it implements, their
//                 `record` block, and the other callables' data
// It throws SceneError when one shader is used in ways that need two different types (two
// payloads, attributes or record types), naming them: split the shader or unify the types.
#pragma once

#include "proceduray/scene/shader_binding_table.hpp"
#include "proceduray/shader/glsl_codegen.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray {

namespace detail {

/// `name` with every character that may not appear in a GLSL identifier replaced by '_'.
inline std::string glsl_identifier(std::string_view name) {
  std::string out(name);
  for (char& c : out) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) c = '_';
  }
  if (out.empty() || (out[0] >= '0' && out[0] <= '9')) out.insert(out.begin(), '_');
  return out;
}

/// The one type a shader's uses agree on, or nullptr; throws when they disagree.
inline const TypeOps* one_type(const std::vector<const TypeOps*>& types, std::string_view shader, const char* what) {
  const TypeOps* found = nullptr;
  for (const TypeOps* t : types) {
    if (t == nullptr) continue;
    if (found != nullptr && found != t) {
      throw SceneError("glsl_for: shader \"" + std::string(shader) + "\" is used with two " + what + " types, " +
                       std::string(found->glsl_name) + " and " + std::string(t->glsl_name) +
                       "; give each use its own shader or one type");
    }
    found = t;
  }
  return found;
}

inline std::string binding_glsl(const Binding& b) {
  const std::string where = "layout(set = " + std::to_string(b.set) + ", binding = " + std::to_string(b.binding);
  const std::string name = glsl_identifier(b.name);
  switch (b.kind) {
    case BindingKind::acceleration_structure: return where + ") uniform accelerationStructureEXT " + name + ";\n";
    case BindingKind::storage_image: return where + ", rgba8) uniform image2D " + name + ";\n";
    case BindingKind::uniform_buffer:
    case BindingKind::storage_buffer: {
      if (b.type == nullptr) {
        throw SceneError("glsl_for: binding \"" + b.name + "\" (set " + std::to_string(b.set) + ", binding " +
                         std::to_string(b.binding) + ") is named but has no type; declare it with a UniformSlot<T>");
      }
      const std::string rule(to_string(b.type->rule));
      const std::string type(b.type->glsl_name);
      if (b.kind == BindingKind::uniform_buffer) {
        return where + ", " + rule + ") uniform " + type + "Uniform {\n" + member_lines(*b.type) + "} " + name + ";\n";
      }
      // A storage buffer holds an array of its type, read as name.data[i].
      return where + ", " + rule + ") readonly buffer " + type + "Buffer {\n    " + type + " data[];\n} " + name + ";\n";
    }
  }
  return {};
}

}  // namespace detail

/// Generated declarations for `shader` as `stage` in `table` (see the top of this header).
inline std::string glsl_for(const ShaderBindingTable& table, ShaderStage stage, std::string_view shader) {
  const Scene& scene = table.scene();
  const PipelinePlan& plan = table.plan();
  const auto rays = scene.rays().size();

  // Every type the scene knows, in a fixed order: payloads, attributes, records, bindings.
  std::vector<const TypeOps*> roots;
  auto add_root = [&](const TypeOps* t) {
    if (t != nullptr && std::find(roots.begin(), roots.end(), t) == roots.end()) roots.push_back(t);
  };
  for (std::uint32_t r = 0; r < rays; ++r) add_root(scene.ray(RayId<>(r)).payload_glsl);
  for (std::uint32_t g = 0; g < scene.hit_groups().size(); ++g) add_root(scene.hit_group(HitGroupId(g)).attribute_glsl);
  for (std::uint32_t l = 0; l < scene.local_signatures().size(); ++l) {
    add_root(scene.local_signature(LocalSignatureId<>(l)).data_glsl);
  }
  const auto callables = scene.callables().size();
  for (std::uint32_t c = 0; c < callables; ++c) add_root(scene.callable(CallableId<>(c)).data_glsl);
  const std::vector<Binding>* bindings = nullptr;
  if (plan.global_signature.valid()) bindings = &scene.global_signature(plan.global_signature).desc.bindings;
  const PushConstantBlock* push = nullptr;
  if (plan.global_signature.valid()) push = &scene.global_signature(plan.global_signature).desc.push_constants;
  if (bindings != nullptr) {
    for (const Binding& b : *bindings) add_root(b.type);
  }
  if (push != nullptr) add_root(push->type);
  std::string out = glsl_declarations(std::span<const TypeOps* const>(roots), true);

  for (std::uint32_t r = 0; r < rays; ++r) {
    const std::string name = detail::glsl_identifier(scene.rays().name(r));
    const RayDesc& desc = scene.ray(RayId<>(r)).desc;
    out += "const uint " + name + "_ray = " + std::to_string(r) + "u;\n";
    out += "const uint " + name + "_flags = " + std::to_string(static_cast<std::uint32_t>(desc.flags)) + "u;\n";
    out += "const uint " + name + "_mask = " + std::to_string(desc.cull_mask) + "u;\n";
  }
  out += "const uint ray_count = " + std::to_string(rays) + "u;\n";
  const auto layers = scene.layers().names();
  for (std::uint32_t l = 0; l < layers.size(); ++l) {
    out += "const uint layer_" + detail::glsl_identifier(layers[l]) + " = " + std::to_string(1u << l) + "u;\n";
  }
  for (std::uint32_t c = 0; c < callables; ++c) {
    out += "const uint " + detail::glsl_identifier(scene.callables().name(c)) + "_callable = " + std::to_string(c) + "u;\n";
  }
  if (bindings != nullptr) {
    for (const Binding& b : *bindings) {
      if (!b.name.empty()) out += detail::binding_glsl(b);
    }
  }
  if (push != nullptr && push->type != nullptr && !push->name.empty()) {
    out += "layout(push_constant, " + std::string(to_string(push->type->rule)) + ") uniform " +
           std::string(push->type->glsl_name) + "Push {\n" + detail::member_lines(*push->type) + "} " +
           detail::glsl_identifier(push->name) + ";\n";
  }

  auto payload = [&](std::uint32_t r, bool incoming, std::string_view name) {
    return "layout(location = " + std::to_string(r) + ") " + (incoming ? "rayPayloadInEXT " : "rayPayloadEXT ") +
           std::string(scene.ray(RayId<>(r)).payload_glsl->glsl_name) + " " + std::string(name) + ";\n";
  };
  auto record_block = [&](const std::vector<const TypeOps*>& types) -> std::string {
    const TypeOps* t = detail::one_type(types, shader, "record data");
    if (t == nullptr) return {};
    return "layout(shaderRecordEXT, " + std::string(to_string(t->rule)) + ") buffer " + std::string(t->glsl_name) +
           "ShaderRecord {\n" + detail::member_lines(*t) + "} record;\n";
  };
  // Outgoing callable data, every callable but `skip` (the one a callable shader receives).
  auto callable_data = [&](std::uint32_t skip) {
    std::string text;
    for (std::uint32_t c = 0; c < callables; ++c) {
      if (c == skip) continue;
      text += "layout(location = " + std::to_string(c) + ") callableDataEXT " +
              std::string(scene.callable(CallableId<>(c)).data_glsl->glsl_name) + " " +
              detail::glsl_identifier(scene.callables().name(c)) + "_call;\n";
    }
    return text;
  };
  auto data_type = [&](const SbtRecord& record) -> const TypeOps* {
    const ShaderTableEntry* e = table.entry(record);
    if (e == nullptr || e->local_signature == no_index) return nullptr;
    return scene.local_signature(LocalSignatureId<>(e->local_signature)).data_glsl;
  };

  switch (stage) {
    case ShaderStage::raygen: {
      for (std::uint32_t r = 0; r < rays; ++r) out += payload(r, false, detail::glsl_identifier(scene.rays().name(r)));
      std::vector<const TypeOps*> records;
      for (const SbtRecord& rec : table.records(SbtRegionKind::raygen)) {
        if (rec.group != no_index && plan.groups[rec.group].name == shader) records.push_back(data_type(rec));
      }
      out += record_block(records);
      out += callable_data(no_index);
      break;
    }
    case ShaderStage::miss: {
      std::vector<const TypeOps*> payloads, records;
      std::uint32_t location = no_index;
      for (std::uint32_t r = 0; r < rays; ++r) {
        if (scene.ray(RayId<>(r)).desc.miss != shader) continue;
        payloads.push_back(scene.ray(RayId<>(r)).payload_glsl);
        location = std::min(location, r);
      }
      for (const SbtRecord& rec : table.records(SbtRegionKind::miss)) {
        if (rec.ray != no_index && scene.ray(RayId<>(rec.ray)).desc.miss == shader) records.push_back(data_type(rec));
      }
      if (detail::one_type(payloads, shader, "payload") != nullptr) out += payload(location, true, "payload");
      out += record_block(records);
      out += callable_data(no_index);
      break;
    }
    case ShaderStage::closest_hit:
    case ShaderStage::any_hit:
    case ShaderStage::intersection: {
      std::vector<const TypeOps*> payloads, attributes, records;
      std::uint32_t location = no_index;
      for (const SbtRecord& rec : table.records(SbtRegionKind::hit)) {
        if (rec.group == no_index) continue;
        const HitGroup& group = scene.hit_group(plan.groups[rec.group].hit_group);
        const std::string& uses = stage == ShaderStage::closest_hit ? group.desc.closest_hit
                                  : stage == ShaderStage::any_hit   ? group.desc.any_hit
                                                                    : group.desc.intersection;
        if (uses != shader) continue;
        attributes.push_back(group.attribute_glsl);
        records.push_back(data_type(rec));
        if (rec.ray != no_index) {
          payloads.push_back(scene.ray(RayId<>(rec.ray)).payload_glsl);
          location = std::min(location, rec.ray);
        }
      }
      if (stage != ShaderStage::intersection && detail::one_type(payloads, shader, "payload") != nullptr) {
        out += payload(location, true, "payload");
      }
      if (const TypeOps* a = detail::one_type(attributes, shader, "hit attribute"); a != nullptr) {
        out += "hitAttributeEXT " + std::string(a->glsl_name) + " hit;\n";
      }
      out += record_block(records);
      if (stage == ShaderStage::closest_hit) {
        for (std::uint32_t r = 0; r < rays; ++r) {
          if (r != location) out += payload(r, false, detail::glsl_identifier(scene.rays().name(r)));
        }
        out += callable_data(no_index);
      }
      break;
    }
    case ShaderStage::callable: {
      std::vector<const TypeOps*> data, records;
      std::uint32_t location = no_index;
      const auto list = table.records(SbtRegionKind::callable);
      for (std::uint32_t c = 0; c < list.size(); ++c) {
        if (scene.callable(CallableId<>(c)).desc.shader != shader) continue;
        data.push_back(scene.callable(CallableId<>(c)).data_glsl);
        records.push_back(data_type(list[c]));
        location = std::min(location, c);
      }
      if (const TypeOps* d = detail::one_type(data, shader, "callable data"); d != nullptr) {
        out += "layout(location = " + std::to_string(location) + ") callableDataInEXT " + std::string(d->glsl_name) +
               " call;\n";
      }
      out += record_block(records);
      out += callable_data(location);
      break;
    }
  }
  return out;
}

}  // namespace proceduray
