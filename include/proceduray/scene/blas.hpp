// Which bottom-level acceleration structure (BLAS) each geometry lives in, and the TLAS
// instances of each BLAS. A geometry gets a BLAS of its own unless GeometryDesc::blas names
// one shared with other geometries of the same kind, policy and instances.
//
//   proceduray::BlasSet set;
//   const auto join = set.check(desc, "pacman", "Scene::add_geometry");   // throws; changes nothing
//   const std::uint32_t geometry_index = set.add(join, geometry_id, desc, "pacman");
//   const auto& instances = set.all()[join.blas].instances;   // the TLAS instances of that BLAS
#pragma once

#include <proceduray/config.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "proceduray/scene/errors.hpp"
#include "proceduray/scene/geometry.hpp"
#include "proceduray/scene/ids.hpp"
#include "proceduray/scene/layers.hpp"

namespace proceduray {

/// A bottom-level acceleration structure: geometries of one kind and the TLAS instances of it.
struct Blas {
  std::string name;                          ///< the shared BLAS name, or the id of its only geometry
  GeometryKind kind = GeometryKind::procedural;  ///< kind of all its geometries
  std::vector<GeometryId> geometries;        ///< in geometry-index order
  std::vector<InstanceTransform> instances;  ///< one TLAS instance each
  std::vector<std::uint8_t> masks;           ///< instance masks, one per instance
  UpdatePolicy update = UpdatePolicy::Static;  ///< of all its geometries
  bool shared = false;                       ///< named by GeometryDesc::blas
};

/// The BLASes of a scene, in creation order (the order of their first geometry).
class BlasSet {
 public:
  /// Where a geometry goes: an existing BLAS or a new one at index `blas`.
  struct Join {
    std::uint32_t blas = 0;
    bool new_blas = true;
  };

  /// Checks that a geometry may join the BLAS `desc` names (or a new one); throws
  /// InvalidGeometryError naming `op` and `id`. Changes nothing.
  Join check(const GeometryDesc& desc, std::string_view id, std::string_view op) const;

  /// Adds geometry `geometry` (named `id`) where check() said; takes the instances out of
  /// `desc`. Returns its geometry index in the BLAS.
  std::uint32_t add(Join join, GeometryId geometry, GeometryDesc& desc, std::string_view id);

  /// All BLASes in creation order.
  std::span<const Blas> all() const { return m_blases; }
  /// The shared BLAS called `name`, or nullptr.
  const Blas* find_shared(std::string_view name) const {
    const auto it = m_shared.find(std::string(name));
    return it == m_shared.end() ? nullptr : &m_blases[it->second];
  }
  /// TLAS instances over all BLASes.
  std::uint64_t instance_count() const {
    std::uint64_t n = 0;
    for (const Blas& b : m_blases) n += b.instances.size();
    return n;
  }
  /// Reserves room for `count` BLASes.
  void reserve(std::size_t count) { m_blases.reserve(count); }

 private:
  static std::vector<std::uint8_t> masks_of(const GeometryDesc& desc) {
    // Geometry validation refused masks over 0xFF before a BLAS sees them.
    if (!desc.instance_masks.empty()) return {desc.instance_masks.begin(), desc.instance_masks.end()};
    return std::vector<std::uint8_t>(desc.instances.size(), static_cast<std::uint8_t>(desc.mask));
  }

  std::vector<Blas> m_blases;
  std::unordered_map<std::string, std::uint32_t> m_shared;
};

}  // namespace proceduray

#include "proceduray/scene/blas-inl.hpp"  // the bodies (config.hpp)
