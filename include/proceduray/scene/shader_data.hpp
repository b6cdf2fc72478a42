// The one seam between scene/ and the shader compatibility layer (shader/): which C++
// types may be a ray payload, hit attributes or record data (shaderRecordEXT block).
//
//   struct Args { glm::vec4 color; std::uint32_t instance; };
//   static_assert(proceduray::RecordData<Args>);
//
// Today any trivially copyable standard-layout type qualifies: its bytes are copied
// verbatim into the SBT. When shader/ lands, constrain ShaderData to its categories
// (RootArguments, Payload, Attributes) here, and nowhere else.
#pragma once

#include <type_traits>

namespace proceduray {

/// A type whose bytes can be handed to a shader as they are.
template <class T>
concept ShaderData = std::is_trivially_copyable_v<T> && std::is_standard_layout_v<T> && !std::is_pointer_v<T>;

/// A ray payload type.
template <class T>
concept PayloadData = ShaderData<T>;
/// A hit attribute type (what an intersection shader reports).
template <class T>
concept AttributeData = ShaderData<T>;
/// A record data type: the shaderRecordEXT block after an SBT handle.
template <class T>
concept RecordData = ShaderData<T>;

}  // namespace proceduray
