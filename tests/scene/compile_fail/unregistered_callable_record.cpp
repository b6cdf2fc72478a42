// A callable record's data must be registered root arguments, like every record's.
// expect: Payload, RootArguments and Attributes take structs registered with PROCEDURAY_STRUCT
// expect-gcc: TintArgs
#include <proceduray/scene/scene.hpp>
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct Tint {
  float value;
};
PROCEDURAY_STRUCT(Tint, scalar, value);
struct TintArgs {
  float factor[4];
};

using Interface = proceduray::ShaderInterface<proceduray::Payload<Tint>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<TintArgs>, proceduray::Attributes<>>;
void bind(proceduray::Scene<Interface>& scene, proceduray::CallableId<Tint> tint) {
  scene.add_callable_record(tint, proceduray::LocalSignatureId<TintArgs>{}, TintArgs{});
}
}  // namespace demo
