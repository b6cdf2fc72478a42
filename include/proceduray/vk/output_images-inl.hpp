// The bodies of proceduray/vk/output_images.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/output_images.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL VkClearColorValue output_clear_value(Output o) {
  VkClearColorValue v{};
  if (o == Output::t) v.float32[0] = -1.0f;
  if (o == Output::ids) v.uint32[0] = v.uint32[1] = v.uint32[2] = v.uint32[3] = 0xffffffffu;
  return v;
}

PROCEDURAY_DECL VkFormat output_format(Output o) {
  switch (o) {
    case Output::t: return VK_FORMAT_R32_SFLOAT;
    case Output::normal: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case Output::ids: return VK_FORMAT_R32G32B32A32_UINT;
    case Output::steps:
    case Output::flags: return VK_FORMAT_R32_UINT;
  }
  return VK_FORMAT_UNDEFINED;
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
