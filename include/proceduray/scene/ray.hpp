// A ray type: its miss shader, its payload type, and the flags and cull mask it is traced with.
//
//   // RayPayload: a registered struct, an alternative of the interface's Payload<...>
//   auto radiance = scene.add_ray<RayPayload>("Radiance", {.miss = "miss.rmiss"});
//   auto shadow = scene.add_ray<ShadowPayload>("Shadow", {
//       .miss = "shadow.rmiss",
//       .flags = proceduray::RayFlags::terminate_on_first_hit | proceduray::RayFlags::skip_closest_hit,
//       .cull_mask = scene.layer_mask({"casts_shadow"})});
//
// Ray index = registration order = miss record index = traceRayEXT's sbtRecordOffset and
// missIndex; the number of rays is traceRayEXT's sbtRecordStride. glsl_for declares
// `<ray>_ray`, `<ray>_flags` and `<ray>_mask` so the shader's traceRayEXT uses what the
// scene declared.
#pragma once

#include <cstdint>
#include <string>
#include <typeindex>
#include <typeinfo>

#include "proceduray/shader/glsl_type.hpp"

namespace proceduray {

/// traceRayEXT's ray flags (gl_RayFlags*EXT, same bits); combine with |.
enum class RayFlags : std::uint32_t {
  none = 0,
  opaque = 0x01,                  ///< treat every geometry as opaque: no any-hit
  no_opaque = 0x02,               ///< treat every geometry as non-opaque: any-hit always runs
  terminate_on_first_hit = 0x04,  ///< accept the first hit found (shadow rays)
  skip_closest_hit = 0x08,        ///< run no closest-hit shader (shadow rays: the miss shader says "lit")
  cull_back_facing = 0x10,        ///< triangles only
  cull_front_facing = 0x20,       ///< triangles only
  cull_opaque = 0x40,             ///< ignore opaque geometry
  cull_no_opaque = 0x80,          ///< ignore non-opaque geometry
};
constexpr RayFlags operator|(RayFlags a, RayFlags b) {
  return static_cast<RayFlags>(static_cast<std::uint32_t>(a) | static_cast<std::uint32_t>(b));
}
constexpr bool has(RayFlags set, RayFlags flag) {
  return (static_cast<std::uint32_t>(set) & static_cast<std::uint32_t>(flag)) != 0;
}

/// What the user declares for a ray type.
struct RayDesc {
  std::string miss;                  ///< miss shader name (the backend maps it to a module); empty = no miss shader
  RayFlags flags = RayFlags::none;   ///< the flags shaders trace it with (`<ray>_flags`); default none
  std::uint8_t cull_mask = 0xFF;     ///< instances it sees: mask & cull_mask != 0 (`<ray>_mask`); default all
};

/// A registered ray type.
struct Ray {
  RayDesc desc;                                   ///< as declared
  std::uint32_t payload_size = 0;                 ///< sizeof(Payload)
  std::type_index payload_type = typeid(void);    ///< Payload, for run-time id checks
  const TypeOps* payload_glsl = nullptr;          ///< Payload's GLSL description (shader layer)
};

}  // namespace proceduray
