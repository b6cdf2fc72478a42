// A callable record's data must be registered root arguments, like every record's.
// expect: no matching function for call to
// expect: proceduray::Scene::add_callable_record(
// expect: required for the satisfaction of
// expect: RootArgumentsData<Arguments>
// expect: [with Arguments = demo::TintArgs]
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

void bind(proceduray::Scene& scene, proceduray::CallableId<Tint> tint) {
  scene.add_callable_record(tint, proceduray::LocalSignatureId<TintArgs>{}, TintArgs{});
}
}  // namespace demo
