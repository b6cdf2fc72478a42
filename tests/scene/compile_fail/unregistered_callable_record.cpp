// A callable record's data must be registered root arguments, like every record's.
// expect-gcc: no matching function for call to
// expect-gcc: proceduray::Scene::add_callable_record(
// expect-gcc: required for the satisfaction of
// expect-gcc: RootArgumentsData<Arguments>
// expect-gcc: [with Arguments = demo::TintArgs]
// expect-clang: no matching member function for call to 'add_callable_record'
// expect-clang: because 'demo::TintArgs' does not satisfy 'RootArgumentsData'
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
