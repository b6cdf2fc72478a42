// The one seam between scene/ and the shader compatibility layer (shader/): which C++
// types may be a ray payload, hit attributes or root arguments (shaderRecordEXT block).
//
//   struct Arguments { glm::vec4 color; std::uint32_t instance; };
//   PROCEDURAY_STRUCT(Arguments, scalar, color, instance);   // at namespace scope, in Arguments' namespace
//   static_assert(proceduray::RootArgumentsData<Arguments>);
//
// A type qualifies only when it is registered with PROCEDURAY_STRUCT: then its layout is
// checked against its GLSL rule and its GLSL declaration is generated from the same list,
// so the bytes the SBT carries are the bytes the shader reads. Hit attributes must also fit
// the 32 bytes every device guarantees. Which interface category a type belongs to
// (Payload, RootArguments, Attributes) is shader::ShaderInterface's business.
#pragma once

#include <type_traits>

#include "proceduray/shader/categories.hpp"
#include "proceduray/shader/glsl_type.hpp"

namespace proceduray {

/// A struct registered with PROCEDURAY_STRUCT, whose bytes can be handed to a shader as they are.
template <class T>
concept ShaderData = RegisteredStruct<T> && std::is_trivially_copyable_v<T> && std::is_standard_layout_v<T>;

/// A ray payload type (rayPayloadEXT).
template <class T>
concept PayloadData = ShaderData<T>;
/// A hit attribute type (hitAttributeEXT, what an intersection shader reports): at most 32 bytes.
template <class T>
concept AttributeData = ShaderData<T> && (sizeof(T) <= max_hit_attribute_size);
/// A root arguments type: the shaderRecordEXT block after an SBT handle (a RootArguments type).
template <class T>
concept RootArgumentsData = ShaderData<T>;

}  // namespace proceduray
