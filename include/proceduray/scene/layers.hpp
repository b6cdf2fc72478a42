// Named visibility layers: up to eight names, each one bit of the 8-bit instance mask that
// traceRayEXT's cull mask is tested against (a ray sees an instance when mask & cull != 0).
//
//   proceduray::Layers layers;
//   layers.add("visible");                                  // bit 0 (0x01)
//   layers.add("casts_shadow");                             // bit 1 (0x02)
//   std::uint8_t ball = layers.mask({"visible", "casts_shadow"});   // 0x03
//   layers.mask({"glass"});   // throws UnknownIdError naming "visible", "casts_shadow"
//
// Scene owns one (Scene::add_layer, Scene::layer_mask); glsl_for declares `layer_<name>`
// for each, so shaders pass the same bits as cull masks.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "proceduray/scene/errors.hpp"

namespace proceduray {

/// Every bit of an instance mask or cull mask: visible to every ray, or sees every instance.
inline constexpr std::uint8_t all_layers = 0xFF;

/// Up to eight named layers, bit i for the i-th added.
class Layers {
 public:
  /// Bits an instance mask has (Vulkan's instance mask is 8 bits wide).
  static constexpr std::size_t max_layers = 8;

  /// Adds a layer and returns its bit; throws DuplicateIdError, or SceneError past eight layers.
  std::uint8_t add(std::string name, std::string_view operation = "Layers::add") {
    if (name.empty()) throw SceneError(std::string(operation) + ": empty layer name; give the layer a name");
    for (const std::string& known : m_names) {
      if (known == name) {
        throw DuplicateIdError(std::string(operation) + ": layer " + detail::quote_id(name) +
                               " already exists; add each layer once");
      }
    }
    if (m_names.size() == max_layers) {
      throw SceneError(std::string(operation) + ": layer " + detail::quote_id(name) + " would be the ninth; an " +
                       "instance mask has 8 bits, so at most 8 layers (have " + detail::quote_list(m_names) +
                       "): merge layers that always go together");
    }
    m_names.push_back(std::move(name));
    return bit(static_cast<std::uint32_t>(m_names.size() - 1));
  }

  /// The bit of one layer; throws UnknownIdError naming the known layers.
  std::uint8_t operator[](std::string_view name) const { return mask({name}); }

  /// The union of the named layers' bits; throws UnknownIdError naming the known layers.
  std::uint8_t mask(std::initializer_list<std::string_view> names, std::string_view operation = "Layers::mask") const {
    return mask(std::span<const std::string_view>(names.begin(), names.size()), operation);
  }
  /// The same for a span of names.
  std::uint8_t mask(std::span<const std::string_view> names, std::string_view operation = "Layers::mask") const {
    std::uint8_t out = 0;
    for (std::string_view name : names) {
      std::uint32_t i = 0;
      while (i < m_names.size() && m_names[i] != name) ++i;
      if (i == m_names.size()) {
        throw UnknownIdError(std::string(operation) + ": no layer " + detail::quote_id(name) + "; the known layers are " +
                             detail::quote_list(m_names) + ": add it first or fix the name");
      }
      out = static_cast<std::uint8_t>(out | bit(i));
    }
    return out;
  }

  /// Layer names, bit order.
  std::span<const std::string> names() const { return m_names; }
  /// Number of layers.
  std::size_t size() const { return m_names.size(); }

 private:
  static std::uint8_t bit(std::uint32_t i) { return static_cast<std::uint8_t>(1u << i); }
  std::vector<std::string> m_names;
};

}  // namespace proceduray
