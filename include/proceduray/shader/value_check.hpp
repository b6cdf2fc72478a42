// Checks a value on its way to a shader: every member (at any depth, array elements included)
// whose type has a validator (proceduray_validate, found by argument-dependent lookup) is
// checked, and a bad one throws UsageError naming the path to it. The renderer runs it on every
// uniform, storage buffer and push constant block it is given (vk/bindings.hpp), so a value a
// shader cannot survive (march knobs of 4 billion steps: a hung device, march/knobs.hpp) is
// refused on the host, at the call that set it.
//
//   struct Gain { float value; };
//   inline void proceduray_validate(const Gain& g, std::string_view where) {   // before it is registered
//     if (!(g.value >= 0.0f)) throw proceduray::UsageError(std::string(where) + ": value must be >= 0");
//   }
//   PROCEDURAY_STRUCT(Gain, scalar, value);
//   struct Mixer { Gain gains[2]; float exposure; };
//   PROCEDURAY_STRUCT(Mixer, scalar, gains, exposure);
//   static_assert(proceduray::type_ops<Mixer>.checked);                // through its members
//   Mixer mixer{};
//   proceduray::check_value(mixer, "uniform 'mixer'");   // e.g. "uniform 'mixer'.gains[1]: value must be >= 0"
//   proceduray::check_value(mixer, [] { return std::string("built only on a failure"); });
//
// A type takes part by declaring its validator in its own namespace, before it is registered.
// Types without validators anywhere inside are not walked (TypeOps::checked is false), and a
// value that passes allocates nothing: the frame loop sets its uniforms every frame.
#pragma once

#include <proceduray/error.hpp>
#include <proceduray/shader/glsl_type.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

namespace proceduray {

namespace detail {

/// Runs the validators in the value at `data`; a failure's message starts with the path to the
/// member (".knobs[4]: ..."), built only then: a value that passes allocates nothing.
inline void check_members(const TypeOps& type, const void* data) {
  if (type.validate != nullptr) type.validate(data, "");
  const auto* bytes = static_cast<const std::byte*>(data);
  if (type.kind == TypeKind::array) {
    for (std::uint32_t i = 0; i < type.count; ++i) {
      try {
        check_members(*type.element, bytes + i * type.element->cpp_size);
      } catch (const UsageError& e) {
        throw UsageError("[" + std::to_string(i) + "]" + e.what());
      }
    }
  } else if (type.kind == TypeKind::structure) {
    for (std::size_t i = 0; i < type.field_count; ++i) {
      const Field& f = type.fields[i];
      if (!f.type->checked) continue;
      try {
        check_members(*f.type, bytes + f.offset);
      } catch (const UsageError& e) {
        throw UsageError("." + std::string(f.name) + e.what());
      }
    }
  }
}

}  // namespace detail

/// Checks `value`: throws UsageError whose message is where() (called only on a failure), the
/// path to the bad member and the validator's words. Nothing to do for types without validators.
template <class T, class Where>
  requires std::is_invocable_v<Where>
void check_value(const T& value, Where&& where) {
  if constexpr (type_ops<T>.checked) {
    try {
      detail::check_members(type_ops<T>, &value);
    } catch (const UsageError& e) {
      throw UsageError(std::string(where()) + e.what());
    }
  }
}

/// The same with a fixed name for the value.
template <class T>
void check_value(const T& value, std::string_view where) {
  check_value(value, [where] { return where; });
}

}  // namespace proceduray
