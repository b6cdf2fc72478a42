// The global signature nearly every image-producing scene has: the TLAS and the output image,
// plus whatever the scene adds (uniforms, storage buffers).
//
//   constexpr proceduray::UniformSlot<SceneConstants> constants{.binding = 2, .name = "constants"};
//   scene.add_global_signature("global", proceduray::default_global_signature({constants}));
//   // GLSL (glsl_for): uniform accelerationStructureEXT tlas; image2D image; SceneConstantsUniform constants
//
// Why: the renderer binds its TLAS to the acceleration-structure binding and its frame to the
// storage-image binding, so every scene spelled out the same two bindings; these numbers and
// names are the convention the examples' and tests' shaders use. Extra bindings must use other
// numbers than 0 and 1 in set 0 (Scene::add_global_signature throws DuplicateIdError otherwise).
#pragma once

#include <proceduray/config.hpp>

#include <cstdint>
#include <utility>
#include <vector>

#include "proceduray/scene/global_signature.hpp"

namespace proceduray {

/// Set 0, binding 0 of default_global_signature: the TLAS, declared as `tlas`.
inline constexpr std::uint32_t default_tlas_binding = 0;
/// Set 0, binding 1 of default_global_signature: the rgba8 output image, declared as `image`.
inline constexpr std::uint32_t default_image_binding = 1;

/// The TLAS at binding 0 ("tlas"), the output image at binding 1 ("image"), then `extra` as given.
PROCEDURAY_DECL GlobalSignatureDesc default_global_signature(std::vector<Binding> extra = {},
                                                             std::uint32_t push_constant_size = 0);

}  // namespace proceduray

#include "proceduray/scene/default_global_signature-inl.hpp"  // the bodies (config.hpp)
