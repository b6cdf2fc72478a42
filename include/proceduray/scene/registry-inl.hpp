// The bodies of proceduray/scene/registry.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/registry.hpp"

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
  if (index == empty_slot) {
    throw UnknownIdError(std::string(operation) + ": a default-constructed " + m_kind + " id names no " + m_kind +
                         "; use the id this scene returned when it was added");
  }
  if (index >= m_names.size()) {
    throw UnknownIdError(std::string(operation) + ": " + m_kind + " #" +
                         std::to_string(index) +
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
