// The bodies of proceduray/scene/shader_stage.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/shader_stage.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL const char* to_string(ShaderStage stage) {
  constexpr const char* names[] = {"raygen", "miss", "closest_hit", "any_hit", "intersection", "callable", "compute"};
  return names[static_cast<std::uint32_t>(stage)];
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
