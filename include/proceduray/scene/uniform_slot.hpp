// Typed buffer bindings: declared once, used both in the global signature and for writes.
//
//   struct SceneConstants { glm::vec4 light; };  PROCEDURAY_STRUCT(SceneConstants, scalar, light);
//   constexpr proceduray::UniformSlot<SceneConstants> constants{.binding = 2};
//   scene.add_global_signature("global", {.bindings = {{BindingKind::acceleration_structure, 0},
//                                                     {BindingKind::storage_image, 1}, constants}});
//   renderer.set(constants, value);   // value must be a SceneConstants: anything else does not compile
//
//   constexpr proceduray::StorageSlot<Tint> tints{.binding = 3, .name = "tints", .per_instance = true};
//   renderer.set_storage(tints, std::span<const Tint>(per_instance));  // GLSL: tints.data[gl_InstanceCustomIndexEXT]
//
//   constexpr proceduray::TextureSlot ground{.binding = 4, .name = "ground"};            // sampler2D ground
//   constexpr proceduray::TextureSlot skies{.binding = 5, .name = "skies", .count = 2, .cube = true};   // samplerCube skies[2]
//   renderer.set_texture(ground, proceduray::load_texture("ground.png"));   // vk/texture.hpp: mips, sampler
//
//   constexpr proceduray::PushConstantSlot<FrameKnobs> knobs{.name = "knobs"};
//   scene.add_global_signature("global", {.bindings = {...}, .push_constants = knobs});
//   renderer.set_push(knobs, frame_knobs);  // recorded with the next trace; GLSL: knobs.member
#pragma once

#include <proceduray/scene/global_signature.hpp>
#include <proceduray/shader/glsl_type.hpp>

#include <cstdint>

namespace proceduray {

/// A uniform buffer binding whose contents are one T, a struct registered with the shader layer.
template <RegisteredStruct T>
struct UniformSlot {
  using type = T;
  std::uint32_t binding = 0;  ///< layout(binding = N)
  std::uint32_t set = 0;      ///< layout(set = N); default 0
  const char* name = "";      ///< GLSL instance name glsl_for declares it under; empty: declared by hand

  /// The binding as the global signature declares it.
  operator Binding() const { return {BindingKind::uniform_buffer, binding, set, 1, name, &type_ops<T>}; }
};

/// A storage buffer binding holding an array of T (GLSL: `name.data[i]`), T registered with the shader layer.
template <RegisteredStruct T>
struct StorageSlot {
  using type = T;
  std::uint32_t binding = 0;  ///< layout(binding = N)
  std::uint32_t set = 0;      ///< layout(set = N); default 0
  const char* name = "";      ///< GLSL instance name glsl_for declares it under; empty: declared by hand
  /// Indexed by gl_InstanceCustomIndexEXT: set_storage refuses fewer elements than TLAS instances
  /// (past the end, a shader reads nothing: instances would render black).
  bool per_instance = false;

  /// The binding as the global signature declares it.
  operator Binding() const { return {BindingKind::storage_buffer, binding, set, 1, name, &type_ops<T>, per_instance}; }
};

/// Textures with their samplers (combined image samplers): `count` 2D textures, or cube maps,
/// sampled in GLSL as `name` (count 1) or `name[i]`, and set with Renderer::set_texture.
struct TextureSlot {
  std::uint32_t binding = 0;  ///< layout(binding = N)
  std::uint32_t set = 0;      ///< layout(set = N); default 0
  const char* name = "";      ///< GLSL name glsl_for declares it under; empty: declared by hand
  std::uint32_t count = 1;    ///< array size; default one texture
  bool cube = false;          ///< samplerCube (cube maps) rather than sampler2D

  /// The binding as the global signature declares it.
  operator Binding() const { return {BindingKind::sampled_image, binding, set, count, name, nullptr, false, cube}; }
};

/// Push constants holding one T (GLSL: `name.member`), T registered with the shader layer. Cheaper
/// than a uniform for a few bytes that change every frame: no buffer, recorded with the trace.
template <RegisteredStruct T>
struct PushConstantSlot {
  using type = T;
  const char* name = "";  ///< GLSL instance name glsl_for declares it under; empty: declared by hand
  /// The block as the global signature declares it.
  operator PushConstantBlock() const { return {&type_ops<T>, name}; }
};

}  // namespace proceduray
