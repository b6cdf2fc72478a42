// A ray type: its miss shader and its payload type.
//
//   struct RayPayload { glm::vec4 color; std::uint32_t depth; };
//   auto radiance = scene.add_ray<RayPayload>("Radiance", {.miss = "miss.rmiss"});
//
// Ray index = registration order = miss record index = traceRayEXT's sbtRecordOffset and
// missIndex; the number of rays is traceRayEXT's sbtRecordStride.
#pragma once

#include <cstdint>
#include <string>
#include <typeindex>
#include <typeinfo>

#include "proceduray/shader/glsl_type.hpp"

namespace proceduray {

/// What the user declares for a ray type.
struct RayDesc {
  std::string miss;  ///< miss shader name (the backend maps it to a module); empty = no miss shader
};

/// A registered ray type.
struct Ray {
  RayDesc desc;                                   ///< as declared
  std::uint32_t payload_size = 0;                 ///< sizeof(Payload)
  std::type_index payload_type = typeid(void);    ///< Payload, for run-time id checks
  const TypeOps* payload_glsl = nullptr;          ///< Payload's GLSL description (shader layer)
};

}  // namespace proceduray
