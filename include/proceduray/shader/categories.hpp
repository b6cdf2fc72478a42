// Closed sets of GPU-visible types (the report's "shader compatibility layer") and the bundle
// that derives the sizes a pipeline needs from them.
//
//   using Interface = proceduray::ShaderInterface<
//       proceduray::Payload<RadiancePayload, ShadowPayload>,     // location = index: 0, 1
//       proceduray::RootComponent<Material, proceduray::DeviceAddress<Sphere>>,
//       proceduray::RootArguments<SphereRecord, BoxRecord>,      // shaderRecordEXT data
//       proceduray::Attributes<SphereHit>>;                      // hitAttributeEXT, <= 32 bytes
//   Interface::max_payload_size;                  // max sizeof over the payloads
//   Interface::max_attribute_size;                // for maxPipelineRayHitAttributeSize
//   Interface::max_root_arguments_size;           // largest root arguments, for the SBT stride
//   Interface::payload_location<ShadowPayload>(); // 1; a type outside Payload does not compile
//   Interface::root_arguments(SphereRecord{...});    // bytes to copy after the group handle
//   Interface::Payloads p = ShadowPayload{};      // each category is a std::variant of its types
//
// Payload, RootArguments and Attributes hold structs registered with PROCEDURAY_STRUCT;
// RootComponent also takes any GLSL member type (values, DeviceAddress<T>). Two types with the
// same GLSL name in one interface do not compile.
#pragma once

#include <proceduray/shader/glsl_type.hpp>

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <tuple>
#include <type_traits>
#include <variant>

namespace proceduray {

/// Vulkan's guaranteed maxRayHitAttributeSize, and the value on every device profiled (lavapipe, H100).
inline constexpr std::size_t max_hit_attribute_size = 32;

/// Which closed set a category is.
enum class CategoryKind : std::uint32_t { payload, root_component, root_arguments, attributes };

namespace detail {

struct NoTypes {};

template <CategoryKind K, class T>
struct CategoryMember {
  static_assert(K == CategoryKind::root_component ? GlslMember<T> : RegisteredStruct<T>,
                "Payload, RootArguments and Attributes take structs registered with PROCEDURAY_STRUCT; "
                "RootComponent takes those or GLSL member types (see the type in the instantiation below)");
  static_assert(K != CategoryKind::attributes || sizeof(T) <= max_hit_attribute_size,
                "Attributes: a hit attribute type is larger than 32 bytes (maxRayHitAttributeSize guaranteed by "
                "Vulkan and on every profiled device); shrink it or pass the data through the payload");
  static constexpr bool ok = true;
};

template <class T, class... Ts>
constexpr std::uint32_t index_in() {
  constexpr bool same[] = {std::is_same_v<T, Ts>..., false};
  std::uint32_t i = 0;
  while (i < sizeof...(Ts) && !same[i]) ++i;
  return i;
}

template <class... Ts>
constexpr bool all_distinct() {
  constexpr std::size_t n = sizeof...(Ts);
  if constexpr (n < 2) {
    return true;
  } else {
    constexpr std::array<std::uint32_t, n> first = {index_in<Ts, Ts...>()...};
    for (std::uint32_t i = 0; i < n; ++i) {
      if (first[i] != i) return false;
    }
    return true;
  }
}

}  // namespace detail

/// Base of the four categories: a std::variant over Ts (empty when no types) plus compile-time facts.
template <CategoryKind K, class... Ts>
struct Category : std::conditional_t<sizeof...(Ts) == 0, detail::NoTypes, std::variant<Ts...>> {
  static_assert((detail::CategoryMember<K, Ts>::ok && ...));
  static_assert(detail::all_distinct<Ts...>(), "a category lists the same type twice; list it once");
  using Base = std::conditional_t<sizeof...(Ts) == 0, detail::NoTypes, std::variant<Ts...>>;
  using Base::Base;

  static constexpr CategoryKind kind = K;                    ///< which category this is
  static constexpr std::size_t count = sizeof...(Ts);       ///< number of types
  static constexpr std::size_t max_size = std::max({std::size_t{0}, sizeof(Ts)...});  ///< largest sizeof; 0 if empty
  /// Whether T is one of the category's types.
  template <class T>
  static constexpr bool contains = (std::is_same_v<T, Ts> || ...);
  /// T's position in the list (its payload location, for Payload).
  template <class T>
  static constexpr std::uint32_t index_of = detail::index_in<T, Ts...>();
  /// The GLSL description of every type, in list order.
  static constexpr std::array<const TypeOps*, sizeof...(Ts)> types = {&type_ops<Ts>...};
};

/// Ray payloads, one per ray type; a payload's index is its rayPayloadEXT location.
template <class... Ts>
struct Payload : Category<CategoryKind::payload, Ts...> {
  using Category<CategoryKind::payload, Ts...>::Category;
};
/// Values and device addresses that root arguments is built from (inline constants, buffers).
template <class... Ts>
struct RootComponent : Category<CategoryKind::root_component, Ts...> {
  using Category<CategoryKind::root_component, Ts...>::Category;
};
/// Root arguments types: each is one shaderRecordEXT block, written after a group handle in the SBT.
template <class... Ts>
struct RootArguments : Category<CategoryKind::root_arguments, Ts...> {
  using Category<CategoryKind::root_arguments, Ts...>::Category;
};
/// Hit attributes reported by intersection shaders (hitAttributeEXT); each at most 32 bytes.
template <class... Ts>
struct Attributes : Category<CategoryKind::attributes, Ts...> {
  using Category<CategoryKind::attributes, Ts...>::Category;
};

/// Satisfied by a category of kind K (Payload<...> for payload, and so on).
template <class C, CategoryKind K>
concept CategoryOf = requires {
  { C::kind } -> std::convertible_to<CategoryKind>;
} && C::kind == K;

namespace detail {

template <class A, class B, bool clash>
struct NameClash {
  static_assert(!clash,
                "ShaderInterface: two different types have the same GLSL struct name (both named in the "
                "instantiation below); rename one, since PROCEDURAY_STRUCT uses the C++ name");
  static constexpr bool ok = true;
};

struct ClashAt {
  std::size_t a = 0, b = 0;
  bool found = false;
};

// Type identity comes from `first` (std::is_same), never from comparing the addresses of two
// type_ops: GCC cannot fold that in a constant expression under -fsanitize=undefined (which
// implies -fno-delete-null-pointer-checks).
template <std::size_t N>
constexpr ClashAt find_name_clash(const std::array<const TypeOps*, N>& t, const std::array<std::uint32_t, N>& first) {
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = i + 1; j < N; ++j) {
      if (first[i] != first[j] && t[i]->kind == TypeKind::structure && t[j]->kind == TypeKind::structure &&
          t[i]->glsl_name == t[j]->glsl_name) {
        return {i, j, true};
      }
    }
  }
  return {};
}

template <class... Ts>
struct TypeList {
  static constexpr std::array<const TypeOps*, sizeof...(Ts)> types = {&type_ops<Ts>...};
  /// For each entry, the index of the first entry of the same type.
  static constexpr std::array<std::uint32_t, sizeof...(Ts)> first = {index_in<Ts, Ts...>()...};
  template <std::size_t I>
  using at = std::tuple_element_t<I, std::tuple<Ts..., void>>;
};

template <class P, class C, class A, class H>
struct JoinTypes;
template <class... P, class... C, class... A, class... H>
struct JoinTypes<Payload<P...>, RootComponent<C...>, RootArguments<A...>, Attributes<H...>> {
  using type = TypeList<P..., C..., A..., H...>;
};

}  // namespace detail

/// The bundle of a scene's four categories, deriving the maxima the pipeline and the SBT need.
template <CategoryOf<CategoryKind::payload> P, CategoryOf<CategoryKind::root_component> C,
          CategoryOf<CategoryKind::root_arguments> A, CategoryOf<CategoryKind::attributes> H>
struct ShaderInterface {
  using Payloads = P;        ///< the Payload category
  using RootComponents = C;  ///< the RootComponent category
  using RootArgumentsSet = A;  ///< the RootArguments category
  using AttributesSet = H;   ///< the Attributes category
  using AllTypes = typename detail::JoinTypes<P, C, A, H>::type;

 private:
  static constexpr detail::ClashAt m_clash = detail::find_name_clash(AllTypes::types, AllTypes::first);
  static_assert(detail::NameClash<typename AllTypes::template at<m_clash.a>,
                                  typename AllTypes::template at<m_clash.b>, m_clash.found>::ok);

 public:
  static constexpr std::size_t max_payload_size = P::max_size;          ///< maxPipelineRayPayloadSize
  static constexpr std::size_t max_attribute_size = H::max_size;        ///< maxPipelineRayHitAttributeSize
  static constexpr std::size_t max_root_arguments_size = A::max_size;   ///< largest root arguments (0: none)
  /// Every type of the interface, categories in order P, C, A, H (roots for GLSL generation).
  static constexpr auto types = AllTypes::types;

  /// The rayPayloadEXT location of payload T (its index in Payload<...>).
  template <class T>
  static constexpr std::uint32_t payload_location() {
    static_assert(P::template contains<T>,
                  "ShaderInterface::payload_location: the type is not in this interface's Payload category; "
                  "add it to Payload<...>");
    return P::template index_of<T>;
  }
  /// T's index in RootArguments<...>.
  template <class T>
  static constexpr std::uint32_t root_arguments_index() {
    static_assert(A::template contains<T>,
                  "ShaderInterface::root_arguments_index: the type is not in this interface's RootArguments "
                  "category; add it to RootArguments<...>");
    return A::template index_of<T>;
  }
  /// T's index in Attributes<...>.
  template <class T>
  static constexpr std::uint32_t attributes_index() {
    static_assert(H::template contains<T>,
                  "ShaderInterface::attributes_index: the type is not in this interface's Attributes category; "
                  "add it to Attributes<...>");
    return H::template index_of<T>;
  }
  /// T's index in RootComponent<...>.
  template <class T>
  static constexpr std::uint32_t root_component_index() {
    static_assert(C::template contains<T>,
                  "ShaderInterface::root_component_index: the type is not in this interface's RootComponent "
                  "category; add it to RootComponent<...>");
    return C::template index_of<T>;
  }
  /// The bytes of root arguments `args` (a RootArguments type), to copy right after a group handle.
  template <class T>
  static std::span<const std::byte, sizeof(T)> root_arguments(const T& args) {
    static_assert(A::template contains<T>,
                  "ShaderInterface::root_arguments: the type is not in this interface's RootArguments category; "
                  "add it to RootArguments<...>");
    return std::as_bytes(std::span<const T, 1>(&args, 1));
  }
};

namespace detail {
/// Whether I is a ShaderInterface (what Scene<I> is declared from).
template <class I>
inline constexpr bool is_shader_interface = requires {
  typename I::Payloads;
  typename I::RootComponents;
  typename I::RootArgumentsSet;
  typename I::AttributesSet;
  I::types;
};
}  // namespace detail

}  // namespace proceduray
