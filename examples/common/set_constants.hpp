// A frame's uniform set on a renderer, for any example scene: through the scene's own
// set_frame(renderer, value) where its namespace has one (found by argument-dependent lookup: the
// paper scene hands its fractals' knobs to the library there), else Renderer::set.
//
//   examples::set_constants(renderer, slot, constants);   // set_frame(renderer, constants), else renderer.set
#pragma once

#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/vk/renderer.hpp>

#include <concepts>

namespace examples {

/// `value`: the slot's type, or one derived from it that carries more (the paper scene's
/// measuring Frame carries the fractals' knobs).
template <class T, std::derived_from<T> V>
void set_constants(proceduray::vk::Renderer& renderer, proceduray::UniformSlot<T> slot, const V& value) {
  if constexpr (requires { set_frame(renderer, value); }) {
    set_frame(renderer, value);
  } else {
    renderer.set(slot, static_cast<const T&>(value));
  }
}

}  // namespace examples
