// The resources of a global signature on the device: descriptor sets laid out from its bindings,
// typed uniform and storage buffers, the storage image and TLAS bindings, and push constants.
//
//   proceduray::vk::Bindings bindings(ctx, plan.global_signature(), structures.tlas().structure());
//   bindings.set(constants_slot, constants);     // typed: another type does not compile
//   bindings.set_storage(tints_slot, tints);     // an array of the slot's type
//   bindings.set_push(knobs_slot, knobs);        // the global signature's typed push constants
//   bindings.bind_image(image.view());           // every storage-image binding
//   bindings.check_ready("Renderer::render");    // throws UsageError naming what was never given
//   bindings.record_upload(frame_cmd);           // changed uniforms, recorded into the frame (vkCmdUpdateBuffer)
//   bindings.upload();                           // or written from the host (no frame may be in flight)
//
// A slot must be the one the global signature was declared with: same set, binding and type
// (a uniform of another type would read or write past its buffer), else UsageError.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/scene/global_signature.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/shader/value_check.hpp>
#include <proceduray/vk/acceleration.hpp>
#include <proceduray/vk/descriptors.hpp>
#include <proceduray/vk/texture.hpp>

#include <cstddef>
#include <cstring>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray::vk {

/// Descriptor sets, buffers and push constants of one global signature.
class Bindings {
 public:
  /// Lays out the sets of `desc` (nullptr: none) and writes `tlas` to its acceleration-structure
  /// bindings; throws UsageError for descriptor arrays, DeviceLimitError for push constants past the device's limit.
  Bindings(const Context& ctx, const GlobalSignatureDesc* desc, const AccelerationStructure& tlas,
           std::uint32_t instance_count = 0);
  Bindings(const Bindings&) = delete;
  Bindings& operator=(const Bindings&) = delete;

  /// Sets a uniform's value, uploaded by record_upload() or upload(). Other types do not compile.
  template <class T>
  void set(UniformSlot<T> slot, const std::type_identity_t<T>& value, std::string_view op = "Bindings::set") {
    Uniform& u = uniform(slot, &type_ops<T>, sizeof(T), op);
    check_value(value, [&] { return std::string(op) + ": uniform '" + slot.name + "'"; });  // before it is kept
    std::memcpy(u.value.data(), &value, sizeof(T));
    u.dirty = true;
  }
  /// Sets a storage buffer's contents, an array of T (at least one element); reallocated when it grows.
  template <class T>
  void set_storage(StorageSlot<T> slot, std::span<const std::type_identity_t<T>> values,
                   std::string_view op = "Bindings::set_storage") {
    for (std::size_t i = 0; type_ops<T>.checked && i < values.size(); ++i) {
      check_value(values[i], [&] { return std::string(op) + ": storage buffer '" + slot.name + "'[" + std::to_string(i) + "]"; });
    }
    set_storage_bytes(slot, &type_ops<T>, std::as_bytes(values), op);
  }
  /// Sets the push constants. Other types do not compile; a slot other than the signature's throws.
  template <class T>
  void set_push(PushConstantSlot<T> slot, const std::type_identity_t<T>& value, std::string_view op = "Bindings::set_push") {
    check_value(value, [&] { return std::string(op) + ": push constants '" + slot.name + "'"; });
    set_push_bytes(slot, &type_ops<T>, std::as_bytes(std::span<const T>(&value, 1)), op);
  }
  /// Writes `view` to every storage-image binding.
  void bind_image(VkImageView view) {
    for (auto [set, binding] : m_images) m_sets[set]->write(binding, view);
  }
  /// Writes an output's image (Plan::outputs) to its binding in set 0.
  void bind_output(std::uint32_t binding, VkImageView view) { m_sets.at(0)->write(binding, view); }
  /// Throws UsageError, naming `op`, when a uniform, storage buffer or push constant block was never given.
  void check_ready(std::string_view op) const;
  /// Copies changed uniform values into their buffers from the host: only when no submitted
  /// frame still reads them.
  void upload() {
    for (Uniform& u : m_uniforms) {
      if (u.dirty) u.buffer->write(std::span<const std::byte>(u.value));
      u.dirty = false;
    }
  }
  /// Records changed uniform values into `cmd` (vkCmdUpdateBuffer, 64 KiB at a time), between
  /// barriers after earlier traces' reads and before this trace's: frames in flight keep the
  /// values they were recorded with, and the host never writes memory the device reads.
  void record_upload(VkCommandBuffer cmd) {
    bool any = false;
    for (const Uniform& u : m_uniforms) any = any || u.dirty;
    if (!any) return;
    barrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_UNIFORM_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
            VK_ACCESS_TRANSFER_WRITE_BIT);
    for (Uniform& u : m_uniforms) {
      if (!u.dirty) continue;
      constexpr std::size_t chunk = 65536;  // vkCmdUpdateBuffer's limit per call
      for (std::size_t at = 0; at < u.value.size(); at += chunk) {
        const std::size_t n = std::min(chunk, u.value.size() - at);
        vkCmdUpdateBuffer(cmd, u.buffer->get(), at, n, u.value.data() + at);
      }
      u.dirty = false;
    }
    barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
            VK_ACCESS_UNIFORM_READ_BIT);
  }
  /// True when the uniform at `slot` has its buffer (set() was called): a first set() writes the
  /// descriptor set, which no submitted frame may be using.
  bool has_buffer(const proceduray::Binding& slot) const {
    for (const Uniform& u : m_uniforms) {
      if (u.set == slot.set && u.binding == slot.binding) return u.buffer != nullptr;
    }
    return false;
  }

  /// Writes a new TLAS (a larger one replaced the old) to the acceleration-structure bindings; no
  /// submitted frame may be using the sets.
  void write_tlas(const AccelerationStructure& tlas) {
    for (const auto& [set, binding] : m_tlas_bindings) m_sets[set]->write(binding, tlas);
  }
  /// Uploads a texture (mips and sampler per `sampler`) into element `index` of a sampled-image
  /// binding; throws UsageError for another kind of binding, an index past its count, or a cube
  /// map for 2D textures and the reverse. No submitted frame may be using the sets.
  void set_texture(const proceduray::Binding& slot, std::uint32_t index, const TextureData& data,
                   const SamplerDesc& sampler, std::string_view op = "Bindings::set_texture");
  /// Throws UsageError naming `op` when a per-instance storage buffer was set with fewer than
  /// `count` elements (an instance is about to be added).
  void check_instance_count(std::uint32_t count, std::string_view op) const;
  /// From now on per-instance storage buffers need `count` elements (instances were added); checks first.
  void set_instance_count(std::uint32_t count, std::string_view op) {
    check_instance_count(count, op);
    m_instance_count = count;
  }

  /// The sets, in set-number order (a gap in the numbers is an empty set).
  std::span<const VkDescriptorSet> sets() const { return m_handles; }
  /// Their layouts, for the pipeline layout.
  std::vector<VkDescriptorSetLayout> layouts() const {
    std::vector<VkDescriptorSetLayout> out;
    for (const auto& s : m_sets) out.push_back(s->layout());
    return out;
  }
  /// Push constant bytes given so far (empty before set_push).
  std::span<const std::byte> push() const { return m_push; }
  /// Bytes of push constants the signature declares, typed or not.
  std::uint32_t push_size() const { return m_push_size; }

 private:
  struct Uniform {
    std::uint32_t set = 0, binding = 0;
    const TypeOps* type = nullptr;
    std::vector<std::byte> value;  // padded to 4-byte words
    std::unique_ptr<Buffer> buffer;
    bool dirty = false;
    std::size_t size = 0;  // bytes of the type given
  };
  struct Storage {
    std::uint32_t set = 0, binding = 0;
    const TypeOps* type = nullptr;
    std::unique_ptr<Buffer> buffer;
    bool per_instance = false;
    std::size_t count = 0;  // elements given
  };
  struct Sampled {
    std::uint32_t set = 0, binding = 0;
    bool cube = false;
    std::vector<std::unique_ptr<Texture>> textures;  // one per array element; null until set
  };
  Uniform& uniform(const proceduray::Binding& slot, const TypeOps* type, std::size_t size, std::string_view op);
  void set_storage_bytes(const proceduray::Binding& slot, const TypeOps* type, std::span<const std::byte> bytes, std::string_view op);
  void set_push_bytes(const PushConstantBlock& slot, const TypeOps* type, std::span<const std::byte> bytes,
                      std::string_view op);
  static void barrier(VkCommandBuffer cmd, VkPipelineStageFlags src_stage, VkAccessFlags src, VkPipelineStageFlags dst_stage,
                      VkAccessFlags dst) {
    auto b = make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    b.srcAccessMask = src;
    b.dstAccessMask = dst;
    vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 1, &b, 0, nullptr, 0, nullptr);
  }
  static std::string where(const proceduray::Binding& b) {
    return "set " + std::to_string(b.set) + " binding " + std::to_string(b.binding);
  }
  static void check_type(const TypeOps* declared, const TypeOps* given, const proceduray::Binding& slot, std::string_view op) {
    if (declared == nullptr || declared == given) return;
    throw UsageError(std::string(op) + ": " + where(slot) + " holds " + std::string(declared->glsl_name) +
                     " in the global signature, not " + std::string(given->glsl_name) +
                     "; pass the slot the signature was declared with");
  }

  const Context* m_ctx;
  std::uint32_t m_instance_count = 0;  // TLAS instances, for per-instance storage buffers
  std::vector<std::unique_ptr<DescriptorSet>> m_sets;  // index = set number
  std::vector<VkDescriptorSet> m_handles;              // their handles, bound every frame
  std::vector<Uniform> m_uniforms;
  std::vector<Storage> m_storage;
  std::vector<Sampled> m_sampled;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> m_images;  // (set, binding) of storage images
  std::vector<std::pair<std::uint32_t, std::uint32_t>> m_tlas_bindings;  // (set, binding) of the TLAS
  PushConstantBlock m_push_block;
  std::uint32_t m_push_size = 0;
  std::vector<std::byte> m_push;
};

}  // namespace proceduray::vk

#include "proceduray/vk/bindings-inl.hpp"  // the bodies (config.hpp)
