// compile(scene): the one pure step from a scene to its Plan (plan.hpp). No device, no Vulkan:
// it runs in a build step as well as before a renderer is made, and gives the same value.
//
//   proceduray::Scene scene = make_scene();
//   proceduray::Plan plan = proceduray::compile(scene);   // throws MissingEntryError, DuplicateIdError, ...
//   plan.pipeline().groups;                                // only the groups records use
//   proceduray::glsl_for(plan, proceduray::ShaderStage::closest_hit, "shade.rchit");
//
// It checks what does not depend on a device (every record has an entry, no two entries bind
// the same record, SBT offsets and instance indices fit Vulkan's 24-bit fields, a raygen exists)
// and derives the rest: TLAS instances and their SBT offsets, record order, groups, stages,
// maximum sizes over what the records use, and each stage's GLSL declarations.
#pragma once

#include <proceduray/config.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "proceduray/scene/errors.hpp"
#include "proceduray/scene/glsl_for.hpp"
#include "proceduray/scene/plan.hpp"
#include "proceduray/scene/scene.hpp"

namespace proceduray {

/// Fills a Plan from a Scene, one pass per method; used by compile().
struct PlanBuilder {
  static constexpr const char* op = "compile";
  const detail::SceneCore& s;
  Plan out{};
  std::uint32_t rays = 0;
  // Entries sorted by what they bind (indices into the scene's entries).
  std::vector<std::uint32_t> raygen, miss_of_ray, callable_entry, wide;
  std::array<std::vector<std::uint32_t>, 2> defaults;  // per hit-group kind, per ray
  std::vector<std::uint32_t> specific_start, specific;  // per TLAS instance: its own entries

  explicit PlanBuilder(const detail::SceneCore& scene) : s(scene), rays(scene.rays().size()) {}

  std::string ray_name(std::uint32_t r) const { return detail::quote_id(s.rays().name(r)); }
  std::string geometry_name(std::uint32_t g) const { return detail::quote_id(s.geometries().name(g)); }
  const Entry& entry(std::uint32_t i) const { return s.entries().all()[i]; }
  std::uint32_t first_instance(std::uint32_t geometry) const {
    return out.m_blases[s.geometries().entities()[geometry].blas].first_instance;
  }
  DuplicateIdError duplicate(std::uint32_t first, std::uint32_t second, const std::string& what) const {
    return DuplicateIdError(std::string(op) + ": entries #" + std::to_string(first) + " and #" + std::to_string(second) +
                            " both bind " + what + "; keep one of them");
  }

  /// Names, geometries, BLASes and TLAS instances (BLAS order, instance order).
  void instances() {
    if (s.entries().raygen_shaders().empty()) {
      throw SceneError(std::string(op) + ": no raygen entry; add one with Scene::add_raygen");
    }
    out.m_scene.value = s.serial();
    out.m_constants = s.constants();
    for (std::uint32_t r = 0; r < rays; ++r) out.m_ray_names.push_back(s.rays().name(r));
    for (std::uint32_t g = 0; g < s.geometries().size(); ++g) {
      const Geometry& geometry = s.geometries().entities()[g];
      out.m_geometries.push_back({s.geometries().name(g), geometry.blas, geometry.geometry_index, geometry.desc.opaque,
                                  geometry.desc.vertex_data.type, geometry.desc.vertex_data.count, geometry.desc.aabbs,
                                  geometry.desc.mesh, geometry.desc.vertex_data.bytes});
    }
    for (std::uint32_t b = 0; b < s.blases().size(); ++b) {
      const Blas& blas = s.blases()[b];
      PlannedBlas& planned = out.m_blases.emplace_back();
      planned = {blas.name, blas.kind, blas.update, {}, static_cast<std::uint32_t>(out.m_instances.size()),
                 static_cast<std::uint32_t>(blas.instances.size())};
      for (GeometryId g : blas.geometries) planned.geometries.push_back(g.index());
      const std::uint64_t count = out.m_instances.size() + blas.instances.size();
      if (count > 0 && !fits_instance_field(count - 1)) {  // instanceCustomIndex of the last instance
        throw DeviceLimitError(std::string(op) + ": the scene has more than " +
                               std::to_string(max_instance_sbt_offset + 1) + " instances, past instanceCustomIndex's "
                               "24 bits (a Vulkan limit on every device); merge geometry into fewer instances");
      }
      for (std::uint32_t i = 0; i < blas.instances.size(); ++i) {
        out.m_instances.push_back({b, i, 0, blas.masks[i], blas.instances[i]});
      }
    }
  }

  /// Sorts the entries: raygen, miss per ray, callable, geometry-wide hit, defaults, per instance.
  void sort_entries() {
    const auto all = s.entries().all();
    miss_of_ray.assign(rays, no_index);
    callable_entry.assign(s.callables().size(), no_index);
    wide.assign(std::size_t{s.geometries().size()} * rays, no_index);
    defaults = {std::vector<std::uint32_t>(rays, no_index), std::vector<std::uint32_t>(rays, no_index)};
    specific_start.assign(out.m_instances.size() + 1, 0);
    for (std::uint32_t i = 0; i < all.size(); ++i) {
      const Entry& e = all[i];
      if (e.region == SbtRegionKind::raygen) {
        raygen.push_back(i);
      } else if (e.region == SbtRegionKind::miss) {
        miss_of_ray[e.ray] = i;
      } else if (e.region == SbtRegionKind::callable) {
        callable_entry[e.shader] = i;
      } else if (e.is_default) {
        defaults[static_cast<std::uint32_t>(s.hit_groups().entities()[e.hit_group].desc.kind)][e.ray] = i;
      } else if (e.instance == all_instances) {
        std::uint32_t& slot = wide[std::size_t{e.geometry} * rays + e.ray];
        if (slot != no_index) {
          throw duplicate(slot, i, "ray " + ray_name(e.ray) + " on all instances of geometry " + geometry_name(e.geometry));
        }
        slot = i;
      } else {
        ++specific_start[first_instance(e.geometry) + e.instance + 1];
      }
    }
    for (std::size_t i = 1; i < specific_start.size(); ++i) specific_start[i] += specific_start[i - 1];
    specific.resize(specific_start.back());
    std::vector<std::uint32_t> fill(specific_start.begin(), specific_start.end() - 1);
    for (std::uint32_t i = 0; i < all.size(); ++i) {
      const Entry& e = all[i];
      if (e.region == SbtRegionKind::hit && !e.is_default && e.instance != all_instances) {
        specific[fill[first_instance(e.geometry) + e.instance]++] = i;
      }
    }
  }

  /// One block of hit records (geometry-major, ray-minor) for `instance` of BLAS `b`, from
  /// geometry-wide entries and defaults.
  void fill_block(const PlannedBlas& b, std::uint32_t instance) {
    for (std::uint32_t g : b.geometries) {
      for (std::uint32_t r = 0; r < rays; ++r) {
        std::uint32_t e = wide[std::size_t{g} * rays + r];
        if (e == no_index) e = defaults[static_cast<std::uint32_t>(b.kind)][r];
        out.m_records[2].push_back(SbtRecord{no_index, e, r, g, instance});
      }
    }
  }
  std::uint32_t block_offset(const PlannedBlas& b, std::uint64_t cursor) const {
    if (!fits_instance_field(cursor)) {
      throw DeviceLimitError(std::string(op) + ": BLAS \"" + b.name + "\" needs instance SBT offset " +
                             std::to_string(cursor) + ", above the 24-bit maximum " +
                             std::to_string(max_instance_sbt_offset) + " of every device; bind entries to whole "
                             "geometries instead of single instances");
    }
    return static_cast<std::uint32_t>(cursor);
  }

  /// Hit records: per BLAS a shared block, then one block per instance with its own entries.
  void hit_records() {
    std::vector<SbtRecord>& hit = out.m_records[2];
    for (PlannedBlas& b : out.m_blases) {
      const std::uint32_t first = b.first_instance;
      bool any_shared = false;
      for (std::uint32_t i = 0; i < b.instance_count; ++i) any_shared |= specific_start[first + i] == specific_start[first + i + 1];
      // Instances added at run time use the block too: kept when a geometry asks, even if unused now.
      for (std::uint32_t g : b.geometries) any_shared |= s.geometries().entities()[g].desc.may_add_instances;
      const std::uint64_t shared_offset = hit.size();
      if (any_shared) {
        b.shared_sbt_offset = block_offset(b, shared_offset);
        fill_block(b, no_index);
      }
      for (std::uint32_t i = 0; i < b.instance_count; ++i) {
        TlasInstance& tlas = out.m_instances[first + i];
        const std::uint32_t begin = specific_start[first + i], end = specific_start[first + i + 1];
        tlas.sbt_offset = static_cast<std::uint32_t>(begin == end ? shared_offset : block_offset(b, hit.size()));
        if (begin == end) continue;
        fill_block(b, i);
        for (std::uint32_t k = begin; k < end; ++k) {
          const Entry& e = entry(specific[k]);
          SbtRecord& record = hit[tlas.sbt_offset + out.m_geometries[e.geometry].geometry_index * rays + e.ray];
          if (record.entry != no_index && !entry(record.entry).is_default && entry(record.entry).instance != all_instances) {
            throw duplicate(record.entry, specific[k], "ray " + ray_name(e.ray) + " on instance " + std::to_string(i) +
                                                           " of geometry " + geometry_name(e.geometry));
          }
          record.entry = specific[k];
        }
      }
    }
    check_missing();
  }

  /// Throws MissingEntryError listing (at most eight) hit records no entry covers.
  void check_missing() const {
    std::uint64_t count = 0;
    std::string list;
    for (const SbtRecord& record : out.m_records[2]) {
      if (record.entry != no_index) continue;
      if (++count > 8) continue;
      list += std::string(list.empty() ? "" : ", ") + "(" + ray_name(record.ray) + ", " + geometry_name(record.geometry) +
              ", " + (record.instance == no_index ? std::string("instances without own entries")
                                                  : "instance " + std::to_string(record.instance)) + ")";
    }
    if (count == 0) return;
    if (count > 8) list += ", and " + std::to_string(count - 8) + " more";
    throw MissingEntryError(std::string(op) + ": " + std::to_string(count) +
                            " hit records have no entry (ray, geometry, instance): " + list +
                            "; add them with Scene::add_hit or declare Scene::set_default_hit for the ray");
  }

  /// Hit records whose root arguments hold a MeshRef: where it is, after checking that the
  /// geometry has vertex data of the MeshRef's vertex type.
  void meshes() {
    for (SbtRecord& record : out.m_records[2]) {
      if (record.entry == no_index || entry(record.entry).local_signature == no_index) continue;
      const TypeOps* args = s.local_signatures().entities()[entry(record.entry).local_signature].arguments_glsl;
      const Field* ref = nullptr;
      for (std::size_t i = 0; args != nullptr && i < args->field_count; ++i) {
        if (args->fields[i].type->mesh_vertex == nullptr) continue;
        if (ref != nullptr) {
          throw SceneError(std::string(op) + ": root arguments " + std::string(args->glsl_name) + " hold two MeshRefs (" +
                           std::string(ref->name) + ", " + std::string(args->fields[i].name) + "); a record reads one "
                           "geometry's mesh: keep one");
        }
        ref = &args->fields[i];
      }
      if (ref == nullptr) continue;
      const Geometry& g = s.geometries().entities()[record.geometry];
      const std::string where = std::string(op) + ": ray " + ray_name(record.ray) + " on geometry " +
                                geometry_name(record.geometry) + " has root arguments " + std::string(args->glsl_name) +
                                " whose member " + std::string(ref->name) + " reads " +
                                std::string(ref->type->mesh_vertex->glsl_name) + " vertices, ";
      if (g.desc.kind != GeometryKind::triangles) {
        throw SceneError(where + "but the geometry is procedural; give its records a local signature without a MeshRef");
      }
      if (!g.desc.vertex_data) {
        throw SceneError(where + "but the geometry has no vertex data; set GeometryDesc::vertex_data = "
                         "VertexData::of(std::span<const " + std::string(ref->type->mesh_vertex->glsl_name) + ">(...))");
      }
      if (g.desc.vertex_data.type != ref->type->mesh_vertex) {
        throw SceneError(where + "but the geometry's vertex data is " + std::string(g.desc.vertex_data.type->glsl_name) +
                         "; make the two the same struct");
      }
      record.mesh_offset = static_cast<std::uint32_t>(ref->offset);
    }
  }

  void pipeline();
  void outputs();
  void depth_counter();
  void fields();
  /// Throws SceneError unless the global signature declares the uniform `p` reads.
  void check_parameter(const DistanceField& f, const FieldParameter& p) const;
  void declarations();
};

/// The outputs' image bindings: set 0, after the highest binding the global signature uses
/// there (a signature is made when the scene has none).

/// Stages and groups that records use, the record groups, and the maxima over used entities.

namespace detail {
/// compile()'s body, once for every interface.
PROCEDURAY_DECL Plan compile_core(const SceneCore& scene);
}  // namespace detail

/// The scene's Plan: records, instances, pipeline plan and GLSL declarations (the interface's
/// alternatives in every stage). Throws MissingEntryError, DuplicateIdError, SceneError (no
/// raygen), DeviceLimitError (24-bit fields).
template <class Interface>
Plan compile(const Scene<Interface>& scene) {
  return detail::compile_core(scene);
}

}  // namespace proceduray

#include "proceduray/scene/compile-inl.hpp"  // the bodies (config.hpp)
