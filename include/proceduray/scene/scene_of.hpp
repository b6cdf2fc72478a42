// A scene whose types are the alternatives of the user's std::variant categories (the report's
// shader compatibility layer): a payload, attribute, root arguments or callable data type that is
// not in its category does not compile.
//
//   using Interface = proceduray::ShaderInterface<
//       proceduray::Payload<RadiancePayload, ShadowPayload>, proceduray::RootComponent<>,
//       proceduray::RootArguments<Material>, proceduray::Attributes<BallHit>>;
//   proceduray::SceneOf<Interface> scene;
//   auto radiance = scene.add_ray<RadiancePayload>("radiance", {.miss = "sky.rmiss"});    // in Payload<...>
//   auto material = scene.add_local_signature<Material>("material");                      // in RootArguments<...>
//   scene.add_hit_group<BallHit>("ball", {.kind = proceduray::HitGroupKind::procedural,   // in Attributes<...>
//                                         .closest_hit = "ball.rchit", .intersection = "ball.rint"});
//   auto sky = scene.add_local_signature("sky", Interface::RootArgumentsSet(Material{}));  // the report's style
//   proceduray::Plan plan = proceduray::compile(scene);   // a SceneOf is a Scene
//
// The maxima the pipeline needs (payload, attributes, root arguments) are derived by compile()
// from the alternatives the records actually use, not from every alternative listed.
#pragma once

#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "proceduray/scene/scene.hpp"
#include "proceduray/shader/categories.hpp"

namespace proceduray {

/// A Scene that accepts only the types of Interface's categories (a ShaderInterface).
template <class Interface>
class SceneOf : public Scene {
 public:
  using Categories = Interface;  ///< the ShaderInterface the scene's types come from

  /// Scene::add_ray, for a payload in Interface's Payload<...>.
  template <class Payload>
  RayId<Payload> add_ray(std::string id, RayDesc desc) {
    static_assert(Interface::Payloads::template contains<Payload>,
                  "SceneOf::add_ray: the payload type (Payload in the instantiation above) is not an alternative "
                  "of the interface's Payload<...> category; add it there");
    return Scene::add_ray<Payload>(std::move(id), std::move(desc));
  }

  /// Scene::add_hit_group, for attributes in Interface's Attributes<...> (void: none, or triangles).
  template <class Attributes = void>
  HitGroupId add_hit_group(std::string id, HitGroupDesc desc) {
    static_assert(std::is_void_v<Attributes> || Interface::AttributesSet::template contains<Attributes>,
                  "SceneOf::add_hit_group: the attribute type (Attributes in the instantiation above) is not an "
                  "alternative of the interface's Attributes<...> category; add it there");
    return Scene::add_hit_group<Attributes>(std::move(id), std::move(desc));
  }

  /// Scene::add_local_signature, for root arguments in Interface's RootArguments<...>.
  template <class Arguments>
  LocalSignatureId<Arguments> add_local_signature(std::string id) {
    static_assert(Interface::RootArgumentsSet::template contains<Arguments>,
                  "SceneOf::add_local_signature: the root arguments type (Arguments in the instantiation above) is not an "
                  "alternative of the interface's RootArguments<...> category; add it there");
    return Scene::add_local_signature<Arguments>(std::move(id));
  }
  /// The report's style: the root arguments type is the alternative `type` holds.
  LocalSignatureId<> add_local_signature(std::string id, const typename Interface::RootArgumentsSet& type) {
    return std::visit([&]<class Arguments>(const Arguments&) { return LocalSignatureId<>(add_local_signature<Arguments>(std::move(id))); },
                      static_cast<const typename Interface::RootArgumentsSet::Base&>(type));
  }

  /// Scene::add_callable, for callable data in Interface's Payload<...> (it travels like a payload).
  template <class Data>
  CallableId<Data> add_callable(std::string id, CallableDesc desc) {
    static_assert(Interface::Payloads::template contains<Data>,
                  "SceneOf::add_callable: the callable data type (Data in the instantiation above) is not an "
                  "alternative of the interface's Payload<...> category; add it there");
    return Scene::add_callable<Data>(std::move(id), std::move(desc));
  }
};

}  // namespace proceduray
