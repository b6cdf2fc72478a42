// The global signature: descriptor bindings and push constants every shader sees
// (DXR's global root signature; in Vulkan, descriptor set layouts + a push constant range).
//
//   auto global = scene.add_global_signature("Global", {.bindings = {
//       {.kind = proceduray::BindingKind::acceleration_structure, .binding = 0},
//       {.kind = proceduray::BindingKind::storage_image, .binding = 1},
//       {.kind = proceduray::BindingKind::uniform_buffer, .binding = 2}},
//     .push_constant_size = 16});
//
// Typed push constants (declared in GLSL by glsl_for, written with Renderer::set_push):
//   constexpr proceduray::PushConstantSlot<Frame> frame{.name = "frame"};   // uniform_slot.hpp
//   scene.add_global_signature("Global", {.bindings = {...}, .push_constants = frame});
#pragma once

#include <proceduray/config.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "proceduray/scene/errors.hpp"
#include "proceduray/shader/glsl_type.hpp"

namespace proceduray {

/// What a descriptor binding holds. output_image: a per-pixel output's storage image, added by
/// compile() for Scene::set_outputs (never declared by the user); the renderer binds its own
/// image there, not the colour image. sampled_image: textures with their samplers (combined
/// image samplers: TextureSlot, set with Renderer::set_texture), 2D or cube, `count` of them.
enum class BindingKind : std::uint32_t {
  acceleration_structure, storage_image, uniform_buffer, storage_buffer, output_image, sampled_image
};

PROCEDURAY_DECL const char* to_string(BindingKind kind);

/// One descriptor binding, visible to every ray-tracing stage.
struct Binding {
  BindingKind kind = BindingKind::storage_buffer;  ///< default: storage buffer
  std::uint32_t binding = 0;                       ///< binding number in its set
  std::uint32_t set = 0;                           ///< descriptor set; default 0
  std::uint32_t count = 1;                         ///< array size; default 1
  std::string name;                                ///< GLSL name to declare it under (glsl_for); empty: not declared
  const TypeOps* type = nullptr;                   ///< a uniform or storage buffer's contents (UniformSlot sets it)
  /// A storage buffer indexed by the TLAS instance (gl_InstanceCustomIndexEXT): the renderer
  /// refuses fewer elements than the scene has instances (StorageSlot::per_instance sets it).
  bool per_instance = false;
  bool cube = false;  ///< sampled_image: cube maps (samplerCube) rather than 2D textures (sampler2D)
  friend bool operator==(const Binding&, const Binding&) = default;
};

/// A typed push constant block: its type and the GLSL name it is declared under (PushConstantSlot makes it).
struct PushConstantBlock {
  const TypeOps* type = nullptr;  ///< the block's contents; null: none
  std::string name;               ///< GLSL instance name glsl_for declares it under; empty: declared by hand
  friend bool operator==(const PushConstantBlock&, const PushConstantBlock&) = default;
};

/// What the user declares for a global signature.
struct GlobalSignatureDesc {
  std::vector<Binding> bindings;         ///< descriptor bindings; none by default
  std::uint32_t push_constant_size = 0;  ///< bytes of untyped push constants, a multiple of 4; 0 = none
  PushConstantBlock push_constants{};    ///< typed push constants instead (PushConstantSlot); default none
  /// Bytes of push constants the pipeline declares, typed or not.
  std::uint32_t push_bytes() const {
    return push_constants.type != nullptr ? static_cast<std::uint32_t>(push_constants.type->cpp_size) : push_constant_size;
  }
  friend bool operator==(const GlobalSignatureDesc&, const GlobalSignatureDesc&) = default;
};

/// A registered global signature.
struct GlobalSignature {
  GlobalSignatureDesc desc;  ///< as declared
};

/// Throws SceneError for a (set, binding) used twice, a zero count, a push constant size not a multiple of 4,
/// or both typed and untyped push constants.
PROCEDURAY_DECL void validate(const GlobalSignatureDesc& desc, std::string_view id, std::string_view operation);

}  // namespace proceduray

#include "proceduray/scene/global_signature-inl.hpp"  // the bodies (config.hpp)
