// bool has no portable block layout (use uint32_t).
// expect: static assertion failed: Flags::visible: unsupported member type
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct Flags {
  float weight;
  bool visible;
};
PROCEDURAY_STRUCT(Flags, scalar, weight, visible);
}  // namespace demo
