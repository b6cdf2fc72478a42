// A string-keyed map of one entity kind, in registration order.
//
//   proceduray::Registry<Ray> rays("ray");
//   std::uint32_t i = rays.add("Scene::add_ray", "Radiance", Ray{...});
//   const Ray* maybe = rays.find("Radiance");   // nullptr when absent
//   const Ray& sure = rays.at("Radiance");      // throws UnknownIdError naming the nearest ids
//
// The Scene holds one Registry per entity kind; ids are indices into it.
#pragma once

#include <proceduray/config.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "proceduray/scene/errors.hpp"

namespace proceduray {

namespace detail {

/// The ids of one Registry and their hash index: all of a registry that does not depend on the
/// entity type, so it is compiled once rather than once per entity kind.
class IdIndex {
 public:
  explicit IdIndex(std::string kind) : m_kind(std::move(kind)) {}

  /// Throws what insert() after it would: SceneError when empty, DuplicateIdError when taken.
  void check_new(std::string_view operation, std::string_view id) const;
  /// Appends `id` (checked by check_new) and returns its index.
  std::uint32_t insert(std::string id);
  /// The index of `id`, or nullptr; the pointer is valid until the next insert().
  const std::uint32_t* find(std::string_view id) const;
  /// The index of `id`; throws UnknownIdError naming `operation` and the nearest known ids.
  std::uint32_t index_of(std::string_view id, std::string_view operation) const;
  /// Throws UnknownIdError unless `index` names a registered id.
  void check_index(std::uint32_t index, std::string_view operation) const;
  /// Reserves room for `count` ids.
  void reserve(std::size_t count);

  const std::string& kind() const { return m_kind; }
  std::span<const std::string> names() const { return m_names; }
  const std::string& name(std::uint32_t index) const { return m_names.at(index); }
  std::uint32_t size() const { return static_cast<std::uint32_t>(m_names.size()); }

 private:
  static constexpr std::uint32_t empty_slot = 0xFFFF'FFFFu;
  /// One entry of the id index: open addressing, linear probing, at most half full. The ids
  /// live once, in m_names; a slot holds 32 bits of the id's hash and the id's index.
  struct Slot {
    std::uint32_t tag = 0;
    std::uint32_t index = empty_slot;
  };
  static std::uint32_t tag_of(std::string_view id);
  /// The slot holding `id`, or the empty slot where it would go.
  std::size_t probe(std::string_view id, std::uint32_t tag) const;
  void rehash(std::size_t slots);

  std::string m_kind;
  std::vector<std::string> m_names;
  std::vector<Slot> m_slots;  ///< id -> index; size a power of two (or 0 before the first insert)
};

}  // namespace detail

/// Entities of one kind, keyed by string id, indexed by registration order.
template <class Entity>
class Registry {
 public:
  /// `kind` names the entity kind in messages ("ray", "hit group", ...).
  explicit Registry(std::string kind) : m_ids(std::move(kind)) {}

  /// Registers `entity` under `id`; throws DuplicateIdError if `id` is taken. Returns its index.
  std::uint32_t add(std::string_view operation, std::string id, Entity entity) {
    m_ids.check_new(operation, id);
    m_entities.push_back(std::move(entity));
    try {
      return m_ids.insert(std::move(id));
    } catch (...) {  // out of memory: leave the registry as it was
      m_entities.pop_back();
      throw;
    }
  }

  /// Throws what add() would for `id`: SceneError when empty, DuplicateIdError when taken. Changes nothing.
  void check_new(std::string_view operation, std::string_view id) const { m_ids.check_new(operation, id); }
  /// The entity registered as `id`, or nullptr.
  const Entity* find(std::string_view id) const {
    const std::uint32_t* index = m_ids.find(id);
    return index ? &m_entities[*index] : nullptr;
  }
  /// The index of `id`, or nullptr; the pointer is valid until the next add().
  const std::uint32_t* find_index(std::string_view id) const { return m_ids.find(id); }
  /// The index of `id`; throws UnknownIdError naming `operation` and the nearest known ids.
  std::uint32_t index_of(std::string_view id, std::string_view operation = "Registry::at") const {
    return m_ids.index_of(id, operation);
  }
  /// The entity registered as `id`; throws UnknownIdError.
  const Entity& at(std::string_view id, std::string_view operation = "Registry::at") const {
    return m_entities[m_ids.index_of(id, operation)];
  }
  /// The entity at `index`; throws UnknownIdError past the end (an id from another scene).
  const Entity& at(std::uint32_t index, std::string_view operation = "Registry::at") const {
    m_ids.check_index(index, operation);
    return m_entities[index];
  }
  /// Throws UnknownIdError unless `index` names a registered entity.
  void check_index(std::uint32_t index, std::string_view operation) const { m_ids.check_index(index, operation); }
  /// The id string of entity `index`.
  const std::string& name(std::uint32_t index) const { return m_ids.name(index); }

  /// Number of registered entities.
  std::uint32_t size() const { return static_cast<std::uint32_t>(m_entities.size()); }
  /// All entities in registration order.
  std::span<const Entity> entities() const { return m_entities; }
  /// All ids in registration order.
  std::span<const std::string> names() const { return m_ids.names(); }
  /// The entity kind as used in messages.
  const std::string& kind() const { return m_ids.kind(); }

  auto begin() const { return m_entities.begin(); }
  auto end() const { return m_entities.end(); }

  /// Reserves room for `count` entities.
  void reserve(std::size_t count) {
    m_entities.reserve(count);
    m_ids.reserve(count);
  }

 private:
  detail::IdIndex m_ids;
  std::vector<Entity> m_entities;
};

}  // namespace proceduray

#if PROCEDURAY_BODIES

#include <algorithm>
#include <functional>

namespace proceduray::detail {

PROCEDURAY_DECL void IdIndex::check_new(std::string_view operation, std::string_view id) const {
  if (id.empty()) {
    throw SceneError(std::string(operation) + ": empty " + m_kind + " id; give every " + m_kind + " a non-empty name");
  }
  if (const std::uint32_t* taken = find(id)) {
    throw DuplicateIdError(std::string(operation) + ": duplicate " + m_kind + " id \"" + std::string(id) +
                           "\" (already " + m_kind + " #" + std::to_string(*taken) + "); choose a unique id");
  }
}

PROCEDURAY_DECL std::uint32_t IdIndex::insert(std::string id) {
  if (2 * (m_names.size() + 1) > m_slots.size()) rehash(std::max<std::size_t>(16, 2 * m_slots.size()));
  const std::uint32_t tag = tag_of(id);
  Slot& slot = m_slots[probe(id, tag)];
  const auto index = static_cast<std::uint32_t>(m_names.size());
  m_names.push_back(std::move(id));
  slot = Slot{tag, index};
  return index;
}

PROCEDURAY_DECL const std::uint32_t* IdIndex::find(std::string_view id) const {
  if (m_slots.empty()) return nullptr;
  const Slot& slot = m_slots[probe(id, tag_of(id))];
  return slot.index == empty_slot ? nullptr : &slot.index;
}

PROCEDURAY_DECL std::uint32_t IdIndex::index_of(std::string_view id, std::string_view operation) const {
  if (const std::uint32_t* index = find(id)) return *index;
  throw UnknownIdError(std::string(operation) + ": unknown " + m_kind + " id \"" + std::string(id) +
                       "\"; nearest known ids: " + quote_list(nearest_ids(id, m_names)) +
                       "; register it first or fix the spelling");
}

PROCEDURAY_DECL void IdIndex::check_index(std::uint32_t index, std::string_view operation) const {
  if (index >= m_names.size()) {
    throw UnknownIdError(std::string(operation) + ": " + m_kind + " #" +
                         (index == empty_slot ? std::string("(invalid id)") : std::to_string(index)) +
                         " is not registered (" + std::to_string(m_names.size()) + " " + m_kind +
                         " entities); use an id returned by this scene");
  }
}

PROCEDURAY_DECL void IdIndex::reserve(std::size_t count) {
  m_names.reserve(count);
  std::size_t slots = 16;
  while (slots < 2 * count) slots *= 2;
  if (slots > m_slots.size()) rehash(slots);
}

PROCEDURAY_DECL std::uint32_t IdIndex::tag_of(std::string_view id) {
  const std::uint64_t h = std::hash<std::string_view>{}(id);
  return static_cast<std::uint32_t>(h ^ (h >> 32));
}

PROCEDURAY_DECL std::size_t IdIndex::probe(std::string_view id, std::uint32_t tag) const {
  const std::size_t mask = m_slots.size() - 1;
  for (std::size_t i = tag & mask;; i = (i + 1) & mask) {
    const Slot& slot = m_slots[i];
    if (slot.index == empty_slot || (slot.tag == tag && m_names[slot.index] == id)) return i;
  }
}

PROCEDURAY_DECL void IdIndex::rehash(std::size_t slots) {
  std::vector<Slot> old = std::exchange(m_slots, std::vector<Slot>(slots));
  const std::size_t mask = slots - 1;
  for (const Slot& slot : old) {
    if (slot.index == empty_slot) continue;
    std::size_t i = slot.tag & mask;
    while (m_slots[i].index != empty_slot) i = (i + 1) & mask;
    m_slots[i] = slot;
  }
}

}  // namespace proceduray::detail
#endif  // PROCEDURAY_BODIES
