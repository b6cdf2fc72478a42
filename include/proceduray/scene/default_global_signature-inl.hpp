// The bodies of proceduray/scene/default_global_signature.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/default_global_signature.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL GlobalSignatureDesc default_global_signature(std::vector<Binding> extra,
                                                             std::uint32_t push_constant_size) {
  GlobalSignatureDesc desc;
  desc.bindings.push_back({BindingKind::acceleration_structure, default_tlas_binding, 0, 1, "tlas", nullptr});
  desc.bindings.push_back({BindingKind::storage_image, default_image_binding, 0, 1, "image", nullptr});
  for (Binding& b : extra) desc.bindings.push_back(std::move(b));
  desc.push_constant_size = push_constant_size;
  return desc;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
