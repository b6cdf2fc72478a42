// A callable shader: registered by id with the type of the data it is called with.
//
//   // TintCall: a registered struct, an alternative of the interface's Payload<...>
//   auto tint = scene.add_callable<TintCall>("tint", {.shader = "tint.rcall"});
//   scene.add_callable_record(tint, tint_signature, TintArgs{...});   // optional root arguments
//
// Callable index = registration order = the callable region's record index = the index a
// shader passes to executeCallableEXT (glsl_for declares it as `<id>_callable`). The data
// type belongs to the Payload-like category: shaders that call it get a `callableDataEXT`
// variable `<id>_call` at location = callable index; the callable shader gets
// `callableDataInEXT <Data> call`.
#pragma once

#include <cstdint>
#include <string>
#include <typeindex>
#include <typeinfo>

#include "proceduray/shader/glsl_type.hpp"

namespace proceduray {

/// What the user declares for a callable shader.
struct CallableDesc {
  std::string shader;  ///< callable shader name (the backend maps it to a module); required
};

/// A registered callable shader.
struct Callable {
  CallableDesc desc;                            ///< as declared
  std::uint32_t data_size = 0;                  ///< sizeof(Data)
  std::type_index data_type = typeid(void);     ///< Data, for run-time id checks
  const TypeOps* data_glsl = nullptr;           ///< Data's GLSL description (shader layer)
};

}  // namespace proceduray
