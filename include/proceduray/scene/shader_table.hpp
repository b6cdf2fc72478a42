// Shader-table entries (pass one) and their build into a ShaderBindingTable (pass two).
// An entry is a tuple <ray, hit group, local signature, arguments> bound to a geometry and,
// optionally, one of its instances; raygen and miss entries may carry record data too.
//
//   proceduray::ShaderTable table(scene);
//   table.add_raygen("raygen.rgen");
//   table.add_miss(radiance, sky_signature, SkyArgs{...});           // optional: miss records exist per ray
//   table.add_hit(radiance, plane_group, triangle_sig, TriangleArgs{...}, plane);       // all instances
//   table.add_hit(shadow, plane_shadow, triangle_sig, TriangleArgs{...}, plane);
//   for (std::uint32_t i = 0; i < 3; ++i)
//     table.add_hit(radiance, pacman_group, procedural_sig, ProceduralArgs{.instance = i}, pacman, i);
//   table.set_default_hit(shadow, pacman_shadow);       // any procedural (shadow, geometry) left unbound
//   table.add_callable(tint, tint_signature, TintArgs{...});   // optional: callable records exist per callable
//   table.set_max_recursion_depth(2);
//   proceduray::ShaderBindingTable sbt = table.build(limits);
//
// An entry whose arguments type differs from its local signature's does not compile; the
// string-id overload checks it at run time (TypeMismatchError). The order entries are added
// in does not matter: build() assigns every instance's SBT offset and every record's place.
// A hit group must match the geometry's kind (HitGroupKindError); every (ray, geometry,
// instance) needs an entry, instance-specific first, then geometry-wide, then the ray's
// default for the geometry's kind, or build() throws MissingEntryError listing the pairs.
#pragma once

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "proceduray/scene/device_limits.hpp"
#include "proceduray/scene/errors.hpp"
#include "proceduray/scene/ids.hpp"
#include "proceduray/scene/pipeline_plan.hpp"
#include "proceduray/scene/sbt_layout.hpp"
#include "proceduray/scene/scene.hpp"
#include "proceduray/scene/shader_binding_table.hpp"
#include "proceduray/scene/shader_data.hpp"

namespace proceduray {

/// An entry's arguments (Given) have exactly its local signature's record data type (Args).
template <class Given, class Args>
concept ArgumentsMatchSignature = std::same_as<Given, Args>;

/// Shader-table entries of one scene; build() lays them out as a ShaderBindingTable.
class ShaderTable {
 public:
  /// Binds a hit entry to every instance of the geometry's BLAS.
  static constexpr std::uint32_t all_instances = no_index;

  /// Entries for `scene`, which must outlive this table.
  explicit ShaderTable(const Scene& scene) : m_scene(&scene) {}

  /// Adds a raygen record for `shader`, without record data.
  EntryId add_raygen(std::string shader) { return add_raygen_impl(std::move(shader), no_index, nullptr, 0); }
  /// Adds a raygen record for `shader` carrying `data` (type fixed by the local signature).
  template <RecordData Args, class Given>
    requires ArgumentsMatchSignature<Given, Args>
  EntryId add_raygen(std::string shader, LocalSignatureId<Args> signature, const Given& data) {
    return add_raygen_impl(std::move(shader), signature.index(), &data, sizeof(Args));
  }

  /// Gives the miss record of `ray` record data; rays without it get a record with none.
  template <class Payload, RecordData Args, class Given>
    requires ArgumentsMatchSignature<Given, Args>
  EntryId add_miss(RayId<Payload> ray, LocalSignatureId<Args> signature, const Given& data) {
    return add_miss_impl(ray.index(), signature.index(), &data, sizeof(Args));
  }

  /// Gives the record of callable `callable` record data; callables without it get a record with none.
  template <class Data, RecordData Args, class Given>
    requires ArgumentsMatchSignature<Given, Args>
  EntryId add_callable(CallableId<Data> callable, LocalSignatureId<Args> signature, const Given& data) {
    return add_callable_impl(callable.index(), signature.index(), &data, sizeof(Args));
  }

  /// Binds <ray, hit group> (no record data) to a geometry, or one instance of it.
  template <class Payload>
  EntryId add_hit(RayId<Payload> ray, HitGroupId group, GeometryId geometry, std::uint32_t instance = all_instances) {
    return add_hit_impl("ShaderTable::add_hit", ray.index(), group.index(), no_index, nullptr, 0, geometry.index(),
                        instance, false);
  }
  /// Binds <ray, hit group, local signature, arguments> to a geometry, or one instance of it.
  template <class Payload, RecordData Args, class Given>
    requires ArgumentsMatchSignature<Given, Args>
  EntryId add_hit(RayId<Payload> ray, HitGroupId group, LocalSignatureId<Args> signature, const Given& args,
                  GeometryId geometry, std::uint32_t instance = all_instances) {
    return add_hit_impl("ShaderTable::add_hit", ray.index(), group.index(), signature.index(), &args, sizeof(Args),
                        geometry.index(), instance, false);
  }
  /// The same by string ids; throws UnknownIdError, or TypeMismatchError when Args is not the signature's type.
  template <RecordData Args>
  EntryId add_hit(std::string_view ray, std::string_view group, std::string_view signature, const Args& args,
                  std::string_view geometry, std::uint32_t instance = all_instances) {
    const Scene& s = *m_scene;
    return add_hit(s.ray_id(ray), s.hit_group_id(group), s.local_signature_id<Args>(signature), args,
                   s.geometry_id(geometry), instance);
  }

  /// Declares the hit group `ray` uses on geometry of the group's kind that has no entry.
  template <class Payload>
  EntryId set_default_hit(RayId<Payload> ray, HitGroupId group) {
    return add_hit_impl("ShaderTable::set_default_hit", ray.index(), group.index(), no_index, nullptr, 0, no_index,
                        all_instances, true);
  }
  /// The same, with record data.
  template <class Payload, RecordData Args, class Given>
    requires ArgumentsMatchSignature<Given, Args>
  EntryId set_default_hit(RayId<Payload> ray, HitGroupId group, LocalSignatureId<Args> signature, const Given& args) {
    return add_hit_impl("ShaderTable::set_default_hit", ray.index(), group.index(), signature.index(), &args,
                        sizeof(Args), no_index, all_instances, true);
  }

  /// Sets the global signature the pipeline uses; default: none.
  void set_global_signature(GlobalSignatureId id) {
    m_scene->global_signatures().check_index(id.index(), "ShaderTable::set_global_signature");
    m_global_signature = id;
  }
  /// Sets the deepest traceRayEXT nesting the shaders do (1 = rays from raygen only); default 1,
  /// undeclared: a pipeline whose closest-hit, miss, ... shaders trace rays needs it declared (>= 2).
  void set_max_recursion_depth(std::uint32_t depth) {
    if (depth == 0) {
      throw SceneError("ShaderTable::set_max_recursion_depth: depth 0 allows no traceRayEXT at all; use >= 1");
    }
    m_max_recursion_depth = depth;
    m_recursion_depth_declared = true;
  }

  /// All entries in the order they were added.
  std::span<const ShaderTableEntry> entries() const { return m_entries; }
  /// Record data of every entry, back to back.
  std::span<const std::byte> data() const { return m_data; }
  /// The record data of one entry.
  std::span<const std::byte> data(EntryId id) const {
    const ShaderTableEntry& e = m_entries.at(id.index());
    return std::span<const std::byte>(m_data).subspan(e.data_offset, e.data_size);
  }
  /// Raygen shader names, indexed by ShaderTableEntry::shader.
  std::span<const std::string> raygen_shaders() const { return m_raygen_shaders; }
  /// The scene the entries refer to.
  const Scene& scene() const { return *m_scene; }
  /// Reserves room for `entries` entries and `data_bytes` of record data.
  void reserve(std::size_t entries, std::size_t data_bytes) {
    m_entries.reserve(entries);
    m_data.reserve(data_bytes);
  }

  /// Pass two: checks the entries against the scene and `limits` and lays out the table.
  /// Throws MissingEntryError, DuplicateIdError, DeviceLimitError (stride and other limits).
  /// This table must outlive the result and must not be moved while it is used.
  ShaderBindingTable build(const DeviceLimits& limits) const;

 private:
  std::uint64_t push_data(const void* data, std::uint32_t size) {
    const std::uint64_t offset = m_data.size();
    m_data.resize(offset + size);
    if (size != 0) std::memcpy(m_data.data() + offset, data, size);
    return offset;
  }
  EntryId push_entry(const ShaderTableEntry& entry) {
    m_entries.push_back(entry);
    return EntryId(static_cast<std::uint32_t>(m_entries.size() - 1));
  }
  EntryId add_raygen_impl(std::string shader, std::uint32_t signature, const void* data, std::uint32_t size) {
    if (shader.empty()) throw SceneError("ShaderTable::add_raygen: empty raygen shader name; name the raygen shader");
    if (signature != no_index) m_scene->local_signatures().check_index(signature, "ShaderTable::add_raygen");
    ShaderTableEntry e;
    e.region = SbtRegionKind::raygen;
    e.local_signature = signature;
    e.shader = static_cast<std::uint32_t>(m_raygen_shaders.size());
    e.data_size = size;
    e.data_offset = push_data(data, size);
    m_raygen_shaders.push_back(std::move(shader));
    return push_entry(e);
  }
  EntryId add_miss_impl(std::uint32_t ray, std::uint32_t signature, const void* data, std::uint32_t size) {
    constexpr std::string_view op = "ShaderTable::add_miss";
    m_scene->rays().check_index(ray, op);
    m_scene->local_signatures().check_index(signature, op);
    for (const ShaderTableEntry& other : m_entries) {
      if (other.region == SbtRegionKind::miss && other.ray == ray) {
        throw DuplicateIdError(std::string(op) + ": ray \"" + m_scene->rays().name(ray) +
                               "\" already has a miss entry; a ray has one miss record: add it once");
      }
    }
    ShaderTableEntry e;
    e.region = SbtRegionKind::miss;
    e.ray = ray;
    e.local_signature = signature;
    e.data_size = size;
    e.data_offset = push_data(data, size);
    return push_entry(e);
  }
  EntryId add_callable_impl(std::uint32_t callable, std::uint32_t signature, const void* data, std::uint32_t size) {
    constexpr std::string_view op = "ShaderTable::add_callable";
    m_scene->callables().check_index(callable, op);
    m_scene->local_signatures().check_index(signature, op);
    for (const ShaderTableEntry& other : m_entries) {
      if (other.region == SbtRegionKind::callable && other.shader == callable) {
        throw DuplicateIdError(std::string(op) + ": callable \"" + m_scene->callables().name(callable) +
                               "\" already has an entry; a callable has one record: add it once");
      }
    }
    ShaderTableEntry e;
    e.region = SbtRegionKind::callable;
    e.shader = callable;
    e.local_signature = signature;
    e.data_size = size;
    e.data_offset = push_data(data, size);
    return push_entry(e);
  }
  EntryId add_hit_impl(std::string_view op, std::uint32_t ray, std::uint32_t group, std::uint32_t signature,
                       const void* data, std::uint32_t size, std::uint32_t geometry, std::uint32_t instance,
                       bool is_default) {
    const Scene& s = *m_scene;
    s.rays().check_index(ray, op);
    const HitGroup& hit_group = s.hit_groups().at(group, op);
    if (signature != no_index) s.local_signatures().check_index(signature, op);
    if (is_default) {
      for (const ShaderTableEntry& other : m_entries) {
        if (other.is_default && other.ray == ray && s.hit_groups().entities()[other.hit_group].desc.kind == hit_group.desc.kind) {
          throw DuplicateIdError(std::string(op) + ": ray \"" + s.rays().name(ray) + "\" already has a default " +
                                 to_string(hit_group.desc.kind) + " hit group (\"" +
                                 s.hit_groups().name(other.hit_group) + "\"); declare one default per ray and kind");
        }
      }
    } else {
      const Geometry& g = s.geometries().at(geometry, op);
      const bool procedural = g.desc.kind == GeometryKind::procedural;
      if (procedural != (hit_group.desc.kind == HitGroupKind::procedural)) {
        throw HitGroupKindError(
            std::string(op) + ": " + to_string(g.desc.kind) + " geometry \"" + s.geometries().name(geometry) +
            "\" bound to " + to_string(hit_group.desc.kind) + " hit group \"" + s.hit_groups().name(group) + "\"" +
            (procedural ? ", which has no intersection shader; bind a procedural hit group"
                        : ", which has an intersection shader; bind a triangles hit group"));
      }
      const auto count = s.blases()[g.blas].instances.size();
      if (instance != all_instances && instance >= count) {
        throw SceneError(std::string(op) + ": instance " + std::to_string(instance) + " of geometry \"" +
                         s.geometries().name(geometry) + "\" does not exist (it has " + std::to_string(count) +
                         " instances); use an index below the count, or all_instances");
      }
    }
    ShaderTableEntry e;
    e.region = SbtRegionKind::hit;
    e.ray = ray;
    e.hit_group = group;
    e.local_signature = signature;
    e.geometry = geometry;
    e.instance = instance;
    e.is_default = is_default;
    e.data_size = size;
    e.data_offset = push_data(data, size);
    return push_entry(e);
  }

  const Scene* m_scene;
  std::vector<ShaderTableEntry> m_entries;
  std::vector<std::byte> m_data;
  std::vector<std::string> m_raygen_shaders;
  GlobalSignatureId m_global_signature;
  std::uint32_t m_max_recursion_depth = 1;
  bool m_recursion_depth_declared = false;
};

inline ShaderBindingTable ShaderTable::build(const DeviceLimits& limits) const {
  constexpr std::string_view op = "ShaderTable::build";
  const Scene& s = *m_scene;
  const std::uint32_t ray_count = s.rays().size();
  const std::span<const Blas> blases = s.blases();
  const std::uint32_t geometry_count = s.geometries().size();
  auto ray_name = [&](std::uint32_t r) { return detail::quote_id(s.rays().name(r)); };
  auto geometry_name = [&](std::uint32_t g) { return detail::quote_id(s.geometries().name(g)); };

  ShaderBindingTable out;
  out.m_scene = m_scene;
  out.m_entries = &m_entries;
  out.m_data = &m_data;
  out.m_ray_count = ray_count;

  if (m_raygen_shaders.empty()) {
    throw SceneError(std::string(op) + ": no raygen entry; add one with ShaderTable::add_raygen");
  }
  if (m_max_recursion_depth > limits.max_ray_recursion_depth) {
    throw DeviceLimitError(std::string(op) + ": max recursion depth " + std::to_string(m_max_recursion_depth) +
                           " exceeds the device's maxRayRecursionDepth " +
                           std::to_string(limits.max_ray_recursion_depth) + "; trace iteratively from raygen instead");
  }

  // TLAS instances: BLAS order, instance order.
  out.m_blas_first_instance.resize(blases.size());
  std::uint64_t instance_total = 0;
  for (std::size_t b = 0; b < blases.size(); ++b) {
    if (blases[b].geometries.size() > limits.max_geometry_count) {
      throw DeviceLimitError(std::string(op) + ": BLAS \"" + blases[b].name + "\" holds " +
                             std::to_string(blases[b].geometries.size()) + " geometries, the device allows " +
                             std::to_string(limits.max_geometry_count) + " (maxGeometryCount); split it");
    }
    out.m_blas_first_instance[b] = static_cast<std::uint32_t>(instance_total);
    instance_total += blases[b].instances.size();
  }
  if (instance_total > limits.max_instance_count) {
    throw DeviceLimitError(std::string(op) + ": the scene has " + std::to_string(instance_total) +
                           " instances, the device allows " + std::to_string(limits.max_instance_count) +
                           " (maxInstanceCount); merge geometry into fewer instances");
  }
  if (instance_total > 0 && !fits_instance_field(instance_total - 1)) {  // the last instanceCustomIndex
    throw DeviceLimitError(std::string(op) + ": the scene has " + std::to_string(instance_total) +
                           " instances, more than instanceCustomIndex's 24 bits (" +
                           std::to_string(max_instance_sbt_offset + 1) + "); merge geometry into fewer instances");
  }
  out.m_instances.resize(instance_total);

  // Sort the entries: raygen, miss per ray, geometry-wide hit, defaults, instance-specific hit.
  std::vector<std::uint32_t> raygen;
  std::vector<std::uint32_t> miss_of_ray(ray_count, no_index);
  std::vector<std::uint32_t> entry_of_callable(s.callables().size(), no_index);
  std::vector<std::uint32_t> wide(std::size_t{geometry_count} * ray_count, no_index);
  std::array<std::vector<std::uint32_t>, 2> defaults{std::vector<std::uint32_t>(ray_count, no_index),
                                                      std::vector<std::uint32_t>(ray_count, no_index)};
  std::vector<std::uint32_t> specific_start(instance_total + 1, 0);
  auto duplicate = [&](std::uint32_t first, std::uint32_t second, const std::string& what) {
    return DuplicateIdError(std::string(op) + ": entries #" + std::to_string(first) + " and #" +
                            std::to_string(second) + " both bind " + what + "; keep one of them");
  };
  for (std::uint32_t i = 0; i < m_entries.size(); ++i) {
    const ShaderTableEntry& e = m_entries[i];
    if (e.region == SbtRegionKind::raygen) {
      raygen.push_back(i);
    } else if (e.region == SbtRegionKind::miss) {
      miss_of_ray[e.ray] = i;
    } else if (e.region == SbtRegionKind::callable) {
      entry_of_callable[e.shader] = i;
    } else if (e.is_default) {
      defaults[static_cast<std::uint32_t>(s.hit_groups().entities()[e.hit_group].desc.kind)][e.ray] = i;
    } else if (e.instance == all_instances) {
      std::uint32_t& slot = wide[std::size_t{e.geometry} * ray_count + e.ray];
      if (slot != no_index) {
        throw duplicate(slot, i, std::string("ray ") + ray_name(e.ray) + " on all instances of geometry " + geometry_name(e.geometry));
      }
      slot = i;
    } else {
      ++specific_start[out.m_blas_first_instance[s.geometries().entities()[e.geometry].blas] + e.instance + 1];
    }
  }
  for (std::size_t i = 1; i < specific_start.size(); ++i) specific_start[i] += specific_start[i - 1];
  std::vector<std::uint32_t> specific(specific_start.back());
  {
    std::vector<std::uint32_t> fill(specific_start.begin(), specific_start.end() - 1);
    for (std::uint32_t i = 0; i < m_entries.size(); ++i) {
      const ShaderTableEntry& e = m_entries[i];
      if (e.region == SbtRegionKind::hit && !e.is_default && e.instance != all_instances) {
        specific[fill[out.m_blas_first_instance[s.geometries().entities()[e.geometry].blas] + e.instance]++] = i;
      }
    }
  }

  // Hit records: per BLAS a shared block, then one block per instance with its own entries.
  std::vector<SbtRecord>& hit = out.m_records[2];
  std::uint64_t missing_count = 0;
  std::vector<std::string> missing;
  std::uint64_t cursor = 0;
  for (std::uint32_t b = 0; b < blases.size(); ++b) {
    const Blas& blas = blases[b];
    const auto instances = static_cast<std::uint32_t>(blas.instances.size());
    if (instances == 0) continue;
    const std::uint32_t first = out.m_blas_first_instance[b];
    const auto block = static_cast<std::uint32_t>(blas.geometries.size() * ray_count);
    const auto kind = static_cast<std::uint32_t>(blas.kind);
    auto fill_block = [&](std::uint32_t instance) {
      for (GeometryId g : blas.geometries) {
        for (std::uint32_t r = 0; r < ray_count; ++r) {
          std::uint32_t entry = wide[std::size_t{g.index()} * ray_count + r];
          if (entry == no_index) entry = defaults[kind][r];
          hit.push_back(SbtRecord{no_index, entry, r, g.index(), instance});
        }
      }
    };
    auto check_offset = [&](std::uint64_t offset) {
      if (!fits_instance_field(offset)) {
        throw DeviceLimitError(std::string(op) + ": BLAS \"" + blas.name + "\" needs instance SBT offset " +
                               std::to_string(offset) + ", above the 24-bit maximum " +
                               std::to_string(max_instance_sbt_offset) +
                               "; bind entries to whole geometries instead of single instances");
      }
    };
    bool any_shared = false;
    for (std::uint32_t i = 0; i < instances && !any_shared; ++i) {
      any_shared = specific_start[first + i] == specific_start[first + i + 1];
    }
    const std::uint64_t shared_offset = cursor;
    if (any_shared) {
      check_offset(cursor);
      fill_block(no_index);
      cursor += block;
    }
    for (std::uint32_t i = 0; i < instances; ++i) {
      TlasInstance& tlas = out.m_instances[first + i];
      tlas.blas = b;
      tlas.instance = i;
      tlas.mask = blas.masks[i];
      const std::uint32_t begin = specific_start[first + i];
      const std::uint32_t end = specific_start[first + i + 1];
      if (begin == end) {
        tlas.sbt_offset = static_cast<std::uint32_t>(shared_offset);
        continue;
      }
      check_offset(cursor);
      tlas.sbt_offset = static_cast<std::uint32_t>(cursor);
      fill_block(i);
      for (std::uint32_t k = begin; k < end; ++k) {
        const ShaderTableEntry& e = m_entries[specific[k]];
        SbtRecord& record = hit[cursor + s.geometries().entities()[e.geometry].geometry_index * ray_count + e.ray];
        if (record.entry != no_index && !m_entries[record.entry].is_default &&
            m_entries[record.entry].instance != all_instances) {
          throw duplicate(record.entry, specific[k],
                          std::string("ray ") + ray_name(e.ray) + " on instance " + std::to_string(i) + " of geometry " +
                              geometry_name(e.geometry));
        }
        record.entry = specific[k];
      }
      cursor += block;
    }
  }
  for (const SbtRecord& record : hit) {
    if (record.entry != no_index) continue;
    if (++missing_count <= 8) {
      missing.push_back(std::string("(") + ray_name(record.ray) + ", " + geometry_name(record.geometry) + ", " +
                        (record.instance == no_index ? std::string("instances without own entries")
                                                     : std::string("instance ") + std::to_string(record.instance)) +
                        ")");
    }
  }
  if (missing_count != 0) {
    std::string list;
    for (const auto& m : missing) list += (list.empty() ? "" : ", ") + m;
    if (missing_count > missing.size()) list += std::string(", and ") + std::to_string(missing_count - missing.size()) + " more";
    throw MissingEntryError(std::string(op) + ": " + std::to_string(missing_count) +
                            " hit records have no entry (ray, geometry, instance): " + list +
                            "; add them with ShaderTable::add_hit or declare ShaderTable::set_default_hit for the ray");
  }

  // Pipeline plan: only the stages and groups records use.
  PipelinePlan& plan = out.m_plan;
  plan.max_recursion_depth = m_max_recursion_depth;
  plan.recursion_depth_declared = m_recursion_depth_declared;
  plan.global_signature = m_global_signature;
  // A stage is shared by every group that names it, except that an intersection shader gets one
  // stage per any-hit shader it is paired with: lavapipe (Mesa 25.0) binds the any-hit of the
  // first group to an intersection stage for every group sharing it.
  std::map<std::tuple<ShaderStage, std::string, std::string>, std::uint32_t> stage_of;
  auto stage = [&](ShaderStage kind, const std::string& name, const std::string& paired = {}) {
    if (name.empty()) return unused_shader;
    auto [it, inserted] = stage_of.try_emplace({kind, name, paired}, static_cast<std::uint32_t>(plan.stages.size()));
    if (inserted) plan.stages.push_back(PlannedStage{kind, name});
    return it->second;
  };
  std::map<std::pair<ShaderStage, std::string>, std::uint32_t> general_group;
  auto general = [&](ShaderStage kind, const std::string& name) {
    auto [it, inserted] = general_group.try_emplace({kind, name}, static_cast<std::uint32_t>(plan.groups.size()));
    if (inserted) {
      PlannedGroup g;
      g.general = stage(kind, name);
      g.name = name;
      plan.groups.push_back(std::move(g));
    }
    return it->second;
  };
  std::vector<bool> signature_used(s.local_signatures().size(), false);
  auto use = [&](std::uint32_t entry, SbtRegionKind region) {
    if (entry == no_index) return;
    const ShaderTableEntry& e = m_entries[entry];
    auto& max = plan.max_record_data_size[static_cast<std::uint32_t>(region)];
    max = std::max(max, e.data_size);
    if (e.local_signature != no_index) signature_used[e.local_signature] = true;
  };
  for (std::uint32_t entry : raygen) {
    out.m_records[0].push_back(
        SbtRecord{general(ShaderStage::raygen, m_raygen_shaders[m_entries[entry].shader]), entry, no_index, no_index, no_index});
    use(entry, SbtRegionKind::raygen);
  }
  for (std::uint32_t r = 0; r < ray_count; ++r) {
    const Ray& ray = s.rays().entities()[r];
    plan.max_payload_size = std::max(plan.max_payload_size, ray.payload_size);
    const std::uint32_t group = ray.desc.miss.empty() ? no_index : general(ShaderStage::miss, ray.desc.miss);
    out.m_records[1].push_back(SbtRecord{group, miss_of_ray[r], r, no_index, no_index});
    use(miss_of_ray[r], SbtRegionKind::miss);
  }
  std::vector<std::uint32_t> group_of_hit_group(s.hit_groups().size(), no_index);
  for (const SbtRecord& record : hit) {
    group_of_hit_group[m_entries[record.entry].hit_group] = 0;
    use(record.entry, SbtRegionKind::hit);
  }
  for (std::uint32_t h = 0; h < group_of_hit_group.size(); ++h) {
    if (group_of_hit_group[h] == no_index) continue;
    const HitGroup& hg = s.hit_groups().entities()[h];
    PlannedGroup g;
    g.type = hg.desc.kind == HitGroupKind::triangles ? GroupType::triangles_hit : GroupType::procedural_hit;
    g.closest_hit = stage(ShaderStage::closest_hit, hg.desc.closest_hit);
    g.any_hit = stage(ShaderStage::any_hit, hg.desc.any_hit);
    g.intersection = stage(ShaderStage::intersection, hg.desc.intersection, hg.desc.any_hit);
    g.name = s.hit_groups().name(h);
    g.hit_group = HitGroupId(h);
    group_of_hit_group[h] = static_cast<std::uint32_t>(plan.groups.size());
    plan.groups.push_back(std::move(g));
    if (hg.attribute_size > limits.max_ray_hit_attribute_size) {
      throw DeviceLimitError(std::string(op) + ": hit group \"" + s.hit_groups().name(h) + "\" reports " +
                             std::to_string(hg.attribute_size) + " bytes of hit attributes, the device allows " +
                             std::to_string(limits.max_ray_hit_attribute_size) +
                             " (maxRayHitAttributeSize); shrink the attribute struct");
    }
    plan.max_attribute_size = std::max(plan.max_attribute_size, hg.attribute_size);
  }
  for (SbtRecord& record : hit) record.group = group_of_hit_group[m_entries[record.entry].hit_group];
  // Callable records: one per registered callable, in callable-index order, after the hit groups.
  for (std::uint32_t c = 0; c < s.callables().size(); ++c) {
    const std::uint32_t group = general(ShaderStage::callable, s.callables().entities()[c].desc.shader);
    out.m_records[3].push_back(SbtRecord{group, entry_of_callable[c], no_index, no_index, no_index});
    use(entry_of_callable[c], SbtRegionKind::callable);
  }
  for (std::uint32_t i = 0; i < signature_used.size(); ++i) {
    if (signature_used[i]) plan.local_signatures.push_back(LocalSignatureId<>(i));
  }

  out.m_layout = layout_sbt(limits.sbt, {{
      {static_cast<std::uint32_t>(out.m_records[0].size()), plan.max_record_data_size[0]},
      {static_cast<std::uint32_t>(out.m_records[1].size()), plan.max_record_data_size[1]},
      {static_cast<std::uint32_t>(hit.size()), plan.max_record_data_size[2]},
      {static_cast<std::uint32_t>(out.m_records[3].size()), plan.max_record_data_size[3]}}});
  return out;
}

}  // namespace proceduray
