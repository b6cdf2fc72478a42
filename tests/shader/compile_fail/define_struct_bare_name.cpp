// A bare member name (as PROCEDURAY_STRUCT takes) is no member: the macro asks for (type, name).
// expect: static assertion failed: Bare: member b is not (type, name): write each member as (type, name)
#include <proceduray/shader/define_struct.hpp>

PROCEDURAY_DEFINE_STRUCT(Bare, scalar, (float, a), b);
