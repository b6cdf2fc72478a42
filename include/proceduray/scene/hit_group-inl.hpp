// The bodies of proceduray/scene/hit_group.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/hit_group.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL const char* to_string(HitGroupKind kind) { return kind == HitGroupKind::triangles ? "triangles" : "procedural"; }

PROCEDURAY_DECL void validate(const HitGroupDesc& desc, std::string_view id, std::string_view operation) {
  if (desc.kind == HitGroupKind::triangles && !desc.intersection.empty()) {
    throw HitGroupKindError(std::string(operation) + ": triangle hit group \"" + std::string(id) +
                            "\" has intersection shader \"" + desc.intersection +
                            "\"; triangles use the built-in intersection: drop it, or declare the group "
                            "with kind = HitGroupKind::procedural");
  }
  if (desc.kind == HitGroupKind::procedural && desc.intersection.empty()) {
    throw HitGroupKindError(std::string(operation) + ": procedural hit group \"" + std::string(id) +
                            "\" has no intersection shader; AABB geometry needs one: set .intersection");
  }
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
