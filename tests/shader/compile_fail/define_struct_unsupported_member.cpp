// A defined struct goes through PROCEDURAY_STRUCT's checks, with the same messages.
// expect: static assertion failed: Flagged::flag: unsupported member type
// expect: static assertion failed: Flagged::input: the member's name is a reserved GLSL word
#include <proceduray/shader/define_struct.hpp>

PROCEDURAY_DEFINE_STRUCT(Flagged, scalar, (float, a), (bool, flag), (float, input));
