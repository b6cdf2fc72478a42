// A local signature: the type of the root arguments (shaderRecordEXT block) its entries carry
// (DXR's local root signature + root arguments type).
//
//   // ProceduralArgs: a registered struct, an alternative of the interface's RootArguments<...>
//   proceduray::LocalSignatureId<ProceduralArgs> sig =
//       scene.add_local_signature<ProceduralArgs>("Procedural");
//   scene.add_hit(radiance, pacman, sig, ProceduralArgs{...}, geometry);  // Arguments must match
#pragma once

#include <cstdint>
#include <string>
#include <typeindex>
#include <typeinfo>

#include "proceduray/shader/glsl_type.hpp"

namespace proceduray {

/// A registered local signature.
struct LocalSignature {
  std::uint32_t arguments_size = 0;                  ///< sizeof(Arguments): bytes after the handle in each record
  std::type_index arguments_type = typeid(void);     ///< Arguments, for run-time checks of string lookups
  const TypeOps* arguments_glsl = nullptr;           ///< Arguments' GLSL description (shader layer)
};

}  // namespace proceduray
