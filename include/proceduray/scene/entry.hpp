// Shader-table entries as a scene stores them: a tuple <ray, hit group, local signature,
// root arguments> bound to a geometry (or one of its instances), or a raygen, miss or callable
// record. Scene::add_hit and friends make them; compile(scene) lays them out (plan.hpp).
//
//   proceduray::EntryList list;
//   const proceduray::Entry e{.region = proceduray::SbtRegionKind::miss, .ray = 0};
//   const float fog = 0.5f;
//   proceduray::EntryId id = list.push(e, &fog, sizeof fog);
//   std::span<const std::byte> bytes = list.data(list.all()[id.index()]);   // the 4 bytes of fog
//
// Root arguments is copied in when the entry is added: the entry owns its bytes.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "proceduray/scene/ids.hpp"
#include "proceduray/scene/sbt_layout.hpp"

namespace proceduray {

/// Marks an absent index in records and entries.
inline constexpr std::uint32_t no_index = 0xFFFF'FFFFu;
/// Binds a hit entry to every instance of the geometry's BLAS.
inline constexpr std::uint32_t all_instances = no_index;

/// An entry's arguments (Given) have exactly its local signature's root arguments type (Arguments).
template <class Given, class Arguments>
concept ArgumentsMatchSignature = std::same_as<Given, Arguments>;

/// One entry as the user added it; indices refer to the scene's registries.
struct Entry {
  SbtRegionKind region = SbtRegionKind::hit;  ///< raygen, miss, hit or callable
  std::uint32_t ray = no_index;               ///< ray index (miss, hit)
  std::uint32_t hit_group = no_index;         ///< hit group index (hit)
  std::uint32_t local_signature = no_index;   ///< local signature index; no_index = no root arguments
  std::uint32_t geometry = no_index;          ///< geometry index (hit); no_index for a default entry
  std::uint32_t instance = no_index;          ///< instance of the geometry's BLAS; no_index = all instances
  std::uint32_t shader = no_index;            ///< raygen: index into EntryList::raygen_shaders(); callable: its index
  std::uint32_t arguments_size = 0;                ///< root arguments bytes
  std::uint64_t arguments_offset = 0;              ///< where they are in EntryList::data()
  bool is_default = false;                    ///< a per-(ray, kind) default hit entry
  friend bool operator==(const Entry&, const Entry&) = default;
};

/// Entries in the order they were added, with their root arguments back to back.
class EntryList {
 public:
  /// Appends `entry` with `size` bytes of root arguments copied from `data`; returns its id.
  EntryId push(Entry entry, const void* data, std::uint32_t size) {
    entry.arguments_size = size;
    entry.arguments_offset = m_data.size();
    m_data.resize(m_data.size() + size);
    if (size != 0) std::memcpy(m_data.data() + entry.arguments_offset, data, size);
    m_entries.push_back(entry);
    return EntryId(static_cast<std::uint32_t>(m_entries.size() - 1));
  }
  /// Remembers a raygen shader name; returns its index (Entry::shader).
  std::uint32_t add_raygen_shader(std::string name) {
    m_raygen_shaders.push_back(std::move(name));
    return static_cast<std::uint32_t>(m_raygen_shaders.size() - 1);
  }

  /// Every entry, in the order added.
  std::span<const Entry> all() const { return m_entries; }
  /// Root arguments of every entry, back to back.
  std::span<const std::byte> data() const { return m_data; }
  /// One entry's root arguments.
  std::span<const std::byte> data(const Entry& e) const {
    return std::span<const std::byte>(m_data).subspan(e.arguments_offset, e.arguments_size);
  }
  /// Raygen shader names, indexed by Entry::shader.
  std::span<const std::string> raygen_shaders() const { return m_raygen_shaders; }
  /// Reserves room for `entries` entries and `data_bytes` of root arguments.
  void reserve(std::size_t entries, std::size_t data_bytes) {
    m_entries.reserve(entries);
    m_data.reserve(data_bytes);
  }

 private:
  std::vector<Entry> m_entries;
  std::vector<std::byte> m_data;
  std::vector<std::string> m_raygen_shaders;
};

}  // namespace proceduray
