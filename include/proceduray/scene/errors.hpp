// Scene usage errors: every message names the operation, the offending id or value, and the fix.
//
//   try { scene.geometry_id("Pacmn"); }
//   catch (const proceduray::UnknownIdError& e) {
//     // Scene::geometry_id: unknown geometry id "Pacmn"; nearest known ids: "Pacman", ...
//   }
//
// All derive from SceneError, a proceduray::UsageError (std::logic_error): they are bugs in the
// calling code. A scene that does not fit a device throws proceduray::DeviceLimitError (error.hpp),
// a runtime error, not a SceneError.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "proceduray/error.hpp"

namespace proceduray {

/// Base of every scene usage error.
class SceneError : public UsageError {
 public:
  using UsageError::UsageError;
};
/// An id registered twice, or two entries bound to the same (ray, geometry, instance).
class DuplicateIdError : public SceneError {
 public:
  using SceneError::SceneError;
};
/// An id that names no registered entity; the message lists the nearest known ids.
class UnknownIdError : public SceneError {
 public:
  using SceneError::SceneError;
};
/// A run-time type check failed (payload or root arguments type differs from the registered one).
class TypeMismatchError : public SceneError {
 public:
  using SceneError::SceneError;
};
/// Bad geometry: AABB with min > max or non-finite bounds, bad mesh, non-finite or singular transform.
class InvalidGeometryError : public SceneError {
 public:
  using SceneError::SceneError;
};
/// A hit group whose shaders do not fit its kind, or bound to geometry of the other kind.
class HitGroupKindError : public SceneError {
 public:
  using SceneError::SceneError;
};
/// (ray, geometry) pairs with no hit entry and no default entry; the message lists them.
class MissingEntryError : public SceneError {
 public:
  using SceneError::SceneError;
};

namespace detail {

/// `value` in hexadecimal, without a prefix.
inline std::string hex(std::uint32_t value) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out;
  do {
    out.insert(out.begin(), digits[value & 0xF]);
    value >>= 4;
  } while (value != 0);
  return out;
}

/// Levenshtein distance between two ids (case-sensitive).
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// The `count` known ids closest to `wanted` by edit distance (ties keep registration order).
template <class Names>
std::vector<std::string> nearest_ids(std::string_view wanted, const Names& known, std::size_t count = 3) {
  std::vector<std::pair<std::size_t, std::string>> scored;
  std::size_t order = 0;
  for (const auto& name : known) {
    scored.emplace_back(edit_distance(wanted, name) * 1'000'000'000u + order++, std::string(name));
  }
  const std::size_t n = std::min(count, scored.size());
  std::partial_sort(scored.begin(), scored.begin() + static_cast<std::ptrdiff_t>(n), scored.end());
  std::vector<std::string> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(std::move(scored[i].second));
  return out;
}

/// `"name"` for messages (built with appends: g++ 12 warns falsely on '"' + std::string).
inline std::string quote_id(std::string_view name) {
  std::string out;
  out.reserve(name.size() + 2);
  out += '"';
  out += name;
  out += '"';
  return out;
}

/// `"a", "b", "c"` for messages; `(none)` when empty.
inline std::string quote_list(const std::vector<std::string>& names) {
  if (names.empty()) return "(none)";
  std::string out;
  for (const auto& name : names) {
    if (!out.empty()) out += ", ";
    out += quote_id(name);
  }
  return out;
}

}  // namespace detail
}  // namespace proceduray
