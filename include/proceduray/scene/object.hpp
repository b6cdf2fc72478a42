// An object: one geometry, a hit group for every ray type and the entries that bind them, in one
// call. Most scenes are a list of such objects; registering each by hand means one hit group per
// ray type, the geometry, and one entry per ray type (per instance when instances differ).
//
//   auto radiance = scene.add_ray<RadiancePayload>("radiance", {.miss = "radiance.rmiss"});
//   auto shadow   = scene.add_ray<ShadowPayload>("shadow", {.miss = "shadow.rmiss"});   // rays first
//   auto material = scene.add_local_signature<Material>("material");
//   proceduray::add_object<SphereHit>(scene, "spheres",
//       {.geometry = proceduray::GeometryDesc::procedural({box}, {left, right}),
//        .intersection = "sphere.rint",                        // every ray type's intersection
//        .closest_hit = {{radiance, "shade.rchit"}}},          // the shadow ray runs none
//       material, {red, blue});                                // one record per instance, or one for all
//
// registers hit groups "spheres" (ray 0) and "spheres_shadow" (every other ray: "<id>_<ray>"),
// geometry "spheres", and one entry per (ray, record). The hit groups' kind follows the geometry's
// (procedural with AABBs, triangles with a mesh). Every check comes before the first change, so a
// throw leaves the scene as it was.
#pragma once

#include <proceduray/config.hpp>

#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "proceduray/scene/errors.hpp"
#include "proceduray/scene/geometry.hpp"
#include "proceduray/scene/hit_group.hpp"
#include "proceduray/scene/ids.hpp"
#include "proceduray/scene/scene.hpp"
#include "proceduray/scene/shader_data.hpp"

namespace proceduray {

/// A shader that one ray type runs.
struct RayShader {
  RayId<> ray;         ///< the ray type
  std::string shader;  ///< shader name
};

/// What an object is: its geometry and the shaders each ray type runs on it.
struct ObjectDesc {
  GeometryDesc geometry;               ///< triangles or AABBs, with its instances
  std::string intersection;            ///< procedural only: the intersection shader of every ray type
  std::vector<RayShader> closest_hit;  ///< closest-hit shaders; a ray type not listed runs none
  std::vector<RayShader> any_hit;      ///< any-hit shaders; a ray type not listed runs none
};

namespace detail {

/// The hit group name of an object for ray `r`: the id for ray 0, "<id>_<ray>" for the others.
PROCEDURAY_DECL std::string object_group_name(const detail::SceneCore& scene, std::string_view id, std::uint32_t r);

/// The shader `ray` runs from `list`, or "" when it has none; throws for unknown or repeated rays.
PROCEDURAY_DECL std::string shader_of(const detail::SceneCore& scene, const std::vector<RayShader>& list, std::uint32_t ray,
                                      std::string_view id, const char* what);

/// Instances of the object's BLAS: its own, or those of the shared BLAS it joins.
PROCEDURAY_DECL std::size_t object_instances(const detail::SceneCore& scene, const GeometryDesc& g);

/// Registers the object's geometry, then its hit groups (checked first: they cannot throw then); returns the
/// geometry and each ray's group.
template <class Attributes, class AnyScene>
std::pair<GeometryId, std::vector<HitGroupId>> register_object(AnyScene& scene, std::string id, ObjectDesc desc,
                                                                std::size_t records) {
  const std::string where = "add_object: object \"" + id + "\"";
  const std::uint32_t rays = scene.rays().size();
  if (rays == 0) {
    throw SceneError(where + " comes before any ray type; register the rays first (Scene::add_ray), "
                     "each gets a hit group");
  }
  if (scene.find_geometry(id) != nullptr) {
    throw DuplicateIdError(where + ": geometry \"" + id + "\" already exists; give the object another id");
  }
  validate(desc.geometry, id, "add_object");
  const bool procedural = desc.geometry.kind == GeometryKind::procedural;
  if constexpr (!std::is_void_v<Attributes>) {
    if (!procedural) {
      throw HitGroupKindError(where + " is triangles but declares an attribute type (" +
                              std::to_string(sizeof(Attributes)) + " bytes); triangles report the built-in "
                              "barycentrics: call add_object<void>");
    }
  } else if (procedural) {
    // Without a type, glsl_for declares no `hit` and the shaders fail in GLSL ("'hit' : undeclared identifier").
    throw HitGroupKindError(where + " is procedural (AABBs) but declares no attribute type; its intersection "
                            "shader reports the hit attributes its closest-hit shader reads as `hit`: call "
                            "add_object<YourAttributes>(...) with a struct registered by PROCEDURAY_STRUCT");
  }
  const std::size_t instances = object_instances(scene, desc.geometry);
  if (records > 1 && records != instances) {
    throw SceneError(where + " has " + std::to_string(records) + " records for " + std::to_string(instances) +
                     " instances; give one record for all instances, or one per instance");
  }
  std::vector<HitGroupDesc> groups(rays);
  for (std::uint32_t r = 0; r < rays; ++r) {
    const std::string name = object_group_name(scene, id, r);
    if (scene.find_hit_group(name) != nullptr) {
      throw DuplicateIdError(where + ": hit group \"" + name + "\" already exists; give the object another id");
    }
    groups[r] = {.kind = procedural ? HitGroupKind::procedural : HitGroupKind::triangles,
                 .closest_hit = shader_of(scene, desc.closest_hit, r, id, "closest_hit"),
                 .any_hit = shader_of(scene, desc.any_hit, r, id, "any_hit"),
                 .intersection = desc.intersection};
    validate(groups[r], name, "add_object");
  }
  // add_geometry makes the checks left (a shared BLAS of another kind or other instances) before it changes anything.
  const GeometryId geometry = scene.add_geometry(id, std::move(desc.geometry));
  std::vector<HitGroupId> ids;
  for (std::uint32_t r = 0; r < rays; ++r) {
    ids.push_back(scene.template add_hit_group<Attributes>(object_group_name(scene, id, r), std::move(groups[r])));
  }
  return {geometry, std::move(ids)};
}

}  // namespace detail

/// Registers an object whose hit records carry `records` (one for every instance, or one per
/// instance) under `signature`; Attributes is what its intersection shader reports (void for
/// triangles). Throws SceneError and its subclasses, naming the object, before changing anything.
/// Attributes must be in the scene interface's Attributes<...> (else it does not compile).
template <class Attributes = void, class Interface, RootArgumentsData Arguments>
GeometryId add_object(Scene<Interface>& scene, std::string id, ObjectDesc desc, LocalSignatureId<Arguments> signature,
                      std::type_identity_t<std::vector<Arguments>> records) {
  if (records.empty()) {
    throw SceneError("add_object: object \"" + id + "\" has a local signature but no record; give one record for "
                     "all instances, or one per instance (or call add_object without a signature)");
  }
  scene.local_signatures().check_index(signature.index(), "add_object: object \"" + id + "\" signature");
  const auto [geometry, groups] =
      detail::register_object<Attributes>(scene, id, std::move(desc), records.size());
  for (std::uint32_t r = 0; r < groups.size(); ++r) {
    if (records.size() == 1) {
      scene.add_hit(RayId<>(r), groups[r], signature, records[0], geometry);
      continue;
    }
    for (std::uint32_t i = 0; i < records.size(); ++i) {
      scene.add_hit(RayId<>(r), groups[r], signature, records[i], geometry, i);
    }
  }
  return geometry;
}

/// Registers an object whose hit records carry no data.
template <class Attributes = void, class Interface>
GeometryId add_object(Scene<Interface>& scene, std::string id, ObjectDesc desc) {
  const auto [geometry, groups] = detail::register_object<Attributes>(scene, std::move(id), std::move(desc), 0);
  for (std::uint32_t r = 0; r < groups.size(); ++r) scene.add_hit(RayId<>(r), groups[r], geometry);
  return geometry;
}

}  // namespace proceduray

#include "proceduray/scene/object-inl.hpp"  // the bodies (config.hpp)
