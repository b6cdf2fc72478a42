// The bodies of proceduray/scene/global_signature.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/global_signature.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL const char* to_string(BindingKind kind) {
  constexpr const char* names[] = {"acceleration_structure", "storage_image", "uniform_buffer", "storage_buffer",
                                   "output_image", "sampled_image"};
  return names[static_cast<std::uint32_t>(kind)];
}

PROCEDURAY_DECL void validate(const GlobalSignatureDesc& desc, std::string_view id, std::string_view operation) {
  const std::string where = std::string(operation) + ": global signature \"" + std::string(id) + "\"";
  for (std::size_t i = 0; i < desc.bindings.size(); ++i) {
    const Binding& b = desc.bindings[i];
    if (b.kind == BindingKind::output_image) {
      throw SceneError(where + " binding " + std::to_string(b.binding) + " is an output_image; outputs get their "
                       "bindings from compile(): ask for them with Scene::set_outputs");
    }
    if (b.count == 0) {
      throw SceneError(where + " binding " + std::to_string(b.binding) + " has count 0; use count >= 1");
    }
    if (b.count != 1 && b.kind != BindingKind::sampled_image) {
      throw SceneError(where + " binding " + std::to_string(b.binding) + " is " + to_string(b.kind) + " with count " +
                       std::to_string(b.count) + "; only textures (sampled_image) come in arrays: use count 1, or "
                       "one binding each");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (desc.bindings[j].set == b.set && desc.bindings[j].binding == b.binding) {
        throw DuplicateIdError(where + " declares set " + std::to_string(b.set) + " binding " +
                               std::to_string(b.binding) + " twice; give each binding its own number");
      }
    }
  }
  if (desc.push_constants.type != nullptr && desc.push_constant_size != 0) {
    throw SceneError(where + " declares push_constant_size " + std::to_string(desc.push_constant_size) +
                     " and typed push constants (" + std::string(desc.push_constants.type->glsl_name) +
                     "); declare one: the typed block sets the size");
  }
  if (desc.push_bytes() % 4 != 0) {
    throw SceneError(where + " push_constant_size " + std::to_string(desc.push_bytes()) +
                     " is not a multiple of 4; pad the push constant block");
  }
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
