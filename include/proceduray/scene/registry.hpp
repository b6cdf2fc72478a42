// A string-keyed map of one entity kind, in registration order.
//
//   proceduray::Registry<Ray> rays("ray");
//   std::uint32_t i = rays.add("Scene::add_ray", "Radiance", Ray{...});
//   const Ray* maybe = rays.find("Radiance");   // nullptr when absent
//   const Ray& sure = rays.at("Radiance");      // throws UnknownIdError naming the nearest ids
//
// The Scene holds one Registry per entity kind; ids are indices into it.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "proceduray/scene/errors.hpp"

namespace proceduray {

/// Entities of one kind, keyed by string id, indexed by registration order.
template <class Entity>
class Registry {
 public:
  /// `kind` names the entity kind in messages ("ray", "hit group", ...).
  explicit Registry(std::string kind) : m_kind(std::move(kind)) {}

  /// Registers `entity` under `id`; throws DuplicateIdError if `id` is taken. Returns its index.
  std::uint32_t add(std::string_view operation, std::string id, Entity entity) {
    if (id.empty()) {
      throw SceneError(std::string(operation) + ": empty " + m_kind + " id; give every " + m_kind +
                       " a non-empty name");
    }
    const auto index = static_cast<std::uint32_t>(m_entities.size());
    auto [it, inserted] = m_index.try_emplace(id, index);
    if (!inserted) {
      throw DuplicateIdError(std::string(operation) + ": duplicate " + m_kind + " id \"" + id + "\" (already " +
                             m_kind + " #" + std::to_string(it->second) + "); choose a unique id");
    }
    m_names.push_back(std::move(id));
    m_entities.push_back(std::move(entity));
    return index;
  }

  /// The entity registered as `id`, or nullptr.
  const Entity* find(std::string_view id) const {
    const std::uint32_t* index = find_index(id);
    return index ? &m_entities[*index] : nullptr;
  }
  /// The index of `id`, or nullptr.
  const std::uint32_t* find_index(std::string_view id) const {
    auto it = m_index.find(std::string(id));
    return it == m_index.end() ? nullptr : &it->second;
  }
  /// The index of `id`; throws UnknownIdError naming `operation` and the nearest known ids.
  std::uint32_t index_of(std::string_view id, std::string_view operation = "Registry::at") const {
    if (const std::uint32_t* index = find_index(id)) return *index;
    throw UnknownIdError(std::string(operation) + ": unknown " + m_kind + " id \"" + std::string(id) +
                         "\"; nearest known ids: " + detail::quote_list(detail::nearest_ids(id, m_names)) +
                         "; register it first or fix the spelling");
  }
  /// The entity registered as `id`; throws UnknownIdError.
  const Entity& at(std::string_view id, std::string_view operation = "Registry::at") const {
    return m_entities[index_of(id, operation)];
  }
  /// The entity at `index`; throws UnknownIdError past the end (an id from another scene).
  const Entity& at(std::uint32_t index, std::string_view operation = "Registry::at") const {
    check_index(index, operation);
    return m_entities[index];
  }
  /// Throws UnknownIdError unless `index` names a registered entity.
  void check_index(std::uint32_t index, std::string_view operation) const {
    if (index >= m_entities.size()) {
      throw UnknownIdError(std::string(operation) + ": " + m_kind + " #" +
                           (index == 0xFFFF'FFFFu ? std::string("(invalid id)") : std::to_string(index)) +
                           " is not registered (" + std::to_string(m_entities.size()) + " " + m_kind +
                           " entities); use an id returned by this scene");
    }
  }
  /// The id string of entity `index`.
  const std::string& name(std::uint32_t index) const { return m_names.at(index); }

  /// Number of registered entities.
  std::uint32_t size() const { return static_cast<std::uint32_t>(m_entities.size()); }
  /// All entities in registration order.
  std::span<const Entity> entities() const { return m_entities; }
  /// All ids in registration order.
  std::span<const std::string> names() const { return m_names; }
  /// The entity kind as used in messages.
  const std::string& kind() const { return m_kind; }

  auto begin() const { return m_entities.begin(); }
  auto end() const { return m_entities.end(); }

  /// Reserves room for `count` entities.
  void reserve(std::size_t count) {
    m_entities.reserve(count);
    m_names.reserve(count);
    m_index.reserve(count);
  }

 private:
  std::string m_kind;
  std::vector<Entity> m_entities;
  std::vector<std::string> m_names;
  std::unordered_map<std::string, std::uint32_t> m_index;
};

}  // namespace proceduray
