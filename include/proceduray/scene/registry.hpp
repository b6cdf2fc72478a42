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

#include "proceduray/scene/registry-inl.hpp"  // the bodies (config.hpp)
