// A scene, its shader table and the table built for a device, owned together.
//
//   struct MyScene : proceduray::SceneTables {
//     MyScene() {
//       auto radiance = scene.add_ray<Payload>("radiance", {.miss = "miss.rmiss"});
//       auto material = scene.add_local_signature<Material>("material");
//       set_global_signature(proceduray::default_global_signature({constants_slot}));
//       table.add_raygen("raygen.rgen");
//       add_object<SphereHit>("sphere", {.geometry = sphere_geometry, .intersection = "sphere.rint",
//                                        .closest_hit = {{radiance, "shade.rchit"}}}, material, {red});
//     }
//   };
//   MyScene s;
//   proceduray::vk::Renderer renderer(ctx, s.build(ctx.limits()), options);
//
// Why: a ShaderTable points at its Scene and a ShaderBindingTable at both, so neither may move
// or die while the next is used. Holding the three in one object that cannot be copied or moved
// keeps them together and at fixed addresses, and spares every scene the same three members.
// build() may run again after changes; whatever used the previous build must be remade.
#pragma once

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "proceduray/scene/device_limits.hpp"
#include "proceduray/scene/errors.hpp"
#include "proceduray/scene/global_signature.hpp"
#include "proceduray/scene/ids.hpp"
#include "proceduray/scene/object.hpp"
#include "proceduray/scene/scene.hpp"
#include "proceduray/scene/shader_binding_table.hpp"
#include "proceduray/scene/shader_table.hpp"

namespace proceduray {

/// A Scene, its ShaderTable and, after build(), its ShaderBindingTable; neither copyable nor movable.
class SceneTables {
 public:
  SceneTables() = default;
  SceneTables(const SceneTables&) = delete;
  SceneTables& operator=(const SceneTables&) = delete;
  ~SceneTables() = default;

  Scene scene;              ///< entities by id (add rays, signatures, geometry here)
  ShaderTable table{scene};  ///< entries over `scene` (add raygen, hits, recursion depth here)

  /// Registers an object in the scene and its entries in the table (object.hpp).
  template <class Attributes = void, RecordData Args>
  GeometryId add_object(std::string id, ObjectDesc desc, LocalSignatureId<Args> signature,
                        std::type_identity_t<std::vector<Args>> records) {
    return proceduray::add_object<Attributes>(scene, table, std::move(id), std::move(desc), signature,
                                              std::move(records));
  }
  /// Registers an object whose records carry no data.
  template <class Attributes = void>
  GeometryId add_object(std::string id, ObjectDesc desc) {
    return proceduray::add_object<Attributes>(scene, table, std::move(id), std::move(desc));
  }

  /// Registers the global signature as `id` and makes it the one the pipeline uses.
  GlobalSignatureId set_global_signature(GlobalSignatureDesc desc, std::string id = "global") {
    const GlobalSignatureId g = scene.add_global_signature(std::move(id), std::move(desc));
    table.set_global_signature(g);
    return g;
  }

  /// Pass two for a device's limits (ShaderTable::build); the result lives in this object.
  const ShaderBindingTable& build(const DeviceLimits& limits) {
    m_sbt.emplace(table.build(limits));  // build() runs first: a throw keeps the previous table
    return *m_sbt;
  }
  /// True once build() has succeeded.
  bool built() const { return m_sbt.has_value(); }
  /// The last build; throws SceneError before the first.
  const ShaderBindingTable& sbt() const {
    if (!m_sbt) throw SceneError("SceneTables::sbt: the table is not built yet; call build(limits) first");
    return *m_sbt;
  }

 private:
  std::optional<ShaderBindingTable> m_sbt;
};

}  // namespace proceduray
