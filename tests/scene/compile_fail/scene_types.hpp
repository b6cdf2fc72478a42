// The interface the Scene compile checks share: each struct registered, each in one category.
#pragma once

#include <proceduray/scene/object.hpp>
#include <proceduray/scene/scene.hpp>
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct Radiance {
  glm::vec4 color;
};
PROCEDURAY_STRUCT(Radiance, scalar, color);
struct Stray {  // registered, but in no category of Interface
  glm::vec4 value;
};
PROCEDURAY_STRUCT(Stray, scalar, value);
struct Material {
  glm::vec4 albedo;
};
PROCEDURAY_STRUCT(Material, scalar, albedo);
struct Hit {
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(Hit, scalar, normal);
using Interface = proceduray::ShaderInterface<proceduray::Payload<Radiance>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<Material>, proceduray::Attributes<Hit>>;
}  // namespace demo
