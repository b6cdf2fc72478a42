// A callable record's data must be registered record data, like every record's.
// expect: required for the satisfaction of
// expect: RecordData<Args>
// expect: [with Args = demo::TintArgs]
#include <proceduray/scene/shader_table.hpp>
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct Tint {
  float value;
};
PROCEDURAY_STRUCT(Tint, scalar, value);
struct TintArgs {
  float factor[4];
};

void bind(proceduray::ShaderTable& table, proceduray::CallableId<Tint> tint) {
  table.add_callable(tint, proceduray::LocalSignatureId<TintArgs>{}, TintArgs{});
}
}  // namespace demo
