// The bodies of proceduray/vk/bindings.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/bindings.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL Bindings::Bindings(const Context& ctx, const GlobalSignatureDesc* desc, const AccelerationStructure& tlas,
                                   std::uint32_t instance_count)
    : m_ctx(&ctx), m_instance_count(instance_count) {
  if (desc == nullptr) return;
  m_push_block = desc->push_constants;
  m_push_size = desc->push_bytes();
  std::map<std::uint32_t, std::vector<vk::Binding>> by_set;
  std::uint32_t last_set = 0;
  for (const proceduray::Binding& b : desc->bindings) {
    if (b.count != 1 && b.kind != BindingKind::sampled_image) {
      throw UsageError("Renderer: " + where(b) + " is an array of " + std::to_string(b.count) +
                       "; only textures come in arrays: use one binding per resource");
    }
    static constexpr VkDescriptorType types[] = {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR,
                                                 VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                                 VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                                                 VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
    by_set[b.set].push_back({b.binding, types[static_cast<std::uint32_t>(b.kind)], all_ray_tracing_stages, b.count});
    last_set = std::max(last_set, b.set);
  }
  // Set numbers in the pipeline layout are positions: a gap gets an empty set.
  for (std::uint32_t s = 0; s <= last_set && !by_set.empty(); ++s) {
    m_sets.push_back(std::make_unique<DescriptorSet>(ctx, by_set[s]));
    m_handles.push_back(m_sets.back()->get());
  }
  for (const proceduray::Binding& b : desc->bindings) {
    switch (b.kind) {
      case BindingKind::acceleration_structure:
        m_sets[b.set]->write(b.binding, tlas);
        m_tlas_bindings.emplace_back(b.set, b.binding);
        break;
      case BindingKind::storage_image: m_images.emplace_back(b.set, b.binding); break;
      case BindingKind::uniform_buffer: m_uniforms.push_back({b.set, b.binding, b.type, {}, nullptr, false, 0}); break;
      case BindingKind::storage_buffer: m_storage.push_back({b.set, b.binding, b.type, nullptr, b.per_instance}); break;
      case BindingKind::output_image: break;  // the renderer binds each output's image (bind_output)
      case BindingKind::sampled_image: {
        Sampled& t = m_sampled.emplace_back(Sampled{b.set, b.binding, b.cube, {}});
        t.textures.resize(b.count);
        break;
      }
    }
  }
}

PROCEDURAY_DECL Bindings::Uniform& Bindings::uniform(const proceduray::Binding& slot, const TypeOps* type, std::size_t size, std::string_view op) {
  for (Uniform& u : m_uniforms) {
    if (u.set != slot.set || u.binding != slot.binding) continue;
    check_type(u.type, type, slot, op);
    if (!u.buffer) {
      // vkCmdUpdateBuffer writes whole 4-byte words: the buffer and the value are padded to them.
      u.size = size;
      u.value.resize((size + 3) / 4 * 4);
      u.buffer = std::make_unique<Buffer>(*m_ctx, (size + 3) / 4 * 4,
                                          VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
      m_sets[u.set]->write(u.binding, *u.buffer);
    }
    if (u.size != size) {  // an untyped binding given two types
      throw UsageError(std::string(op) + ": " + where(slot) + " was given " + std::to_string(u.size) +
                       " bytes before and " + std::to_string(size) + " now; keep one type per uniform");
    }
    return u;
  }
  throw UsageError(std::string(op) + ": " + where(slot) + " is not a uniform buffer of the global signature; "
                   "declare it there (a UniformSlot converts to its Binding)");
}

PROCEDURAY_DECL void Bindings::set_storage_bytes(const proceduray::Binding& slot, const TypeOps* type, std::span<const std::byte> bytes,
                                                 std::string_view op) {
  for (Storage& s : m_storage) {
    if (s.set != slot.set || s.binding != slot.binding) continue;
    check_type(s.type, type, slot, op);
    if (bytes.empty()) {
      throw UsageError(std::string(op) + ": no elements given for " + where(slot) + "; a storage buffer needs at least one");
    }
    const std::size_t count = s.type != nullptr && s.type->cpp_size > 0 ? bytes.size() / s.type->cpp_size : bytes.size();
    if (s.per_instance && count < m_instance_count) {
      throw UsageError(std::string(op) + ": " + where(slot) + " is indexed per TLAS instance but got " +
                       std::to_string(count) + " elements for " + std::to_string(m_instance_count) +
                       " instances (the ones past the end would read nothing); give one element per instance");
    }
    if (!s.buffer || s.buffer->size() < bytes.size()) {
      s.buffer = std::make_unique<Buffer>(*m_ctx, bytes.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      m_sets[s.set]->write(s.binding, *s.buffer);
    }
    s.buffer->write(bytes);
    s.count = count;
    return;
  }
  throw UsageError(std::string(op) + ": " + where(slot) + " is not a storage buffer of the global signature; "
                   "declare it there (a StorageSlot converts to its Binding)");
}

PROCEDURAY_DECL void Bindings::check_instance_count(std::uint32_t count, std::string_view op) const {
  for (const Storage& s : m_storage) {
    if (!s.per_instance || !s.buffer || s.count >= count) continue;
    throw UsageError(std::string(op) + ": per-instance storage buffer at set " + std::to_string(s.set) + " binding " +
                     std::to_string(s.binding) + " holds " + std::to_string(s.count) + " elements, and the new instance's "
                     "custom index is " + std::to_string(count - 1) + " (it would read past the end); call set_storage "
                     "with at least " + std::to_string(count) + " elements first");
  }
}

PROCEDURAY_DECL void Bindings::set_push_bytes(const PushConstantBlock& slot, const TypeOps* type, std::span<const std::byte> bytes,
                                              std::string_view op) {
  if (m_push_block.type == nullptr) {
    throw UsageError(std::string(op) + ": the global signature declares no typed push constants (" +
                     std::to_string(m_push_size) + " untyped bytes); declare them with "
                     "GlobalSignatureDesc::push_constants = a PushConstantSlot<" + std::string(type->glsl_name) + ">");
  }
  if (m_push_block.type != type || m_push_block.name != slot.name) {
    throw UsageError(std::string(op) + ": the slot holds " + std::string(type->glsl_name) + " \"" + slot.name +
                     "\" but the global signature declares " + std::string(m_push_block.type->glsl_name) + " \"" +
                     m_push_block.name + "\"; pass the slot the signature was declared with");
  }
  m_push.assign(bytes.begin(), bytes.end());
}

PROCEDURAY_DECL void Bindings::set_texture(const proceduray::Binding& slot, std::uint32_t index, const TextureData& data,
                                           const SamplerDesc& sampler, std::string_view op) {
  for (Sampled& t : m_sampled) {
    if (t.set != slot.set || t.binding != slot.binding) continue;
    if (index >= t.textures.size()) {
      throw UsageError(std::string(op) + ": element " + std::to_string(index) + " of " + where(slot) + ", which holds " +
                       std::to_string(t.textures.size()) + " textures; use an index below that");
    }
    if (data.cube() != t.cube) {
      throw UsageError(std::string(op) + ": " + where(slot) + " holds " + (t.cube ? "cube maps" : "2D textures") +
                       " (TextureSlot::cube), given a " + (data.cube() ? "cube map" : "2D texture") +
                       (t.cube ? "; make one with make_cube or load_cube" : "; give it a 2D texture"));
    }
    auto texture = std::make_unique<Texture>(*m_ctx, data, sampler, op);  // throws before any change
    m_sets[t.set]->write(t.binding, index, texture->view(), texture->sampler());
    t.textures[index] = std::move(texture);
    return;
  }
  throw UsageError(std::string(op) + ": " + where(slot) + " is not a texture binding of the global signature; "
                   "declare it there with a TextureSlot");
}

PROCEDURAY_DECL void Bindings::check_ready(std::string_view op) const {
  for (const Uniform& u : m_uniforms) {
    if (!u.buffer) {
      throw UsageError(std::string(op) + ": the uniform at set " + std::to_string(u.set) + " binding " +
                       std::to_string(u.binding) + " was never given a value; call set(slot, value) first");
    }
  }
  for (const Sampled& t : m_sampled) {
    for (std::size_t i = 0; i < t.textures.size(); ++i) {
      if (t.textures[i]) continue;
      throw UsageError(std::string(op) + ": texture " + std::to_string(i) + " at set " + std::to_string(t.set) +
                       " binding " + std::to_string(t.binding) + " was never given; call set_texture(slot, texture" +
                       (t.textures.size() > 1 ? ", sampler, " + std::to_string(i) : std::string()) + ") first");
    }
  }
  for (const Storage& s : m_storage) {
    if (!s.buffer) {
      throw UsageError(std::string(op) + ": the storage buffer at set " + std::to_string(s.set) + " binding " +
                       std::to_string(s.binding) + " was never given data; call set_storage(slot, values) first");
    }
  }
  if (m_push_size != m_push.size()) {
    throw UsageError(std::string(op) + ": the global signature declares " + std::to_string(m_push_size) +
                     " bytes of push constants but " +
                     (m_push_block.type != nullptr
                          ? std::string("they were never given a value; call set_push(slot, value) first")
                          : std::string("they are untyped, so the renderer cannot fill them; declare them with a "
                                        "PushConstantSlot<T>")));
  }
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
