// `sample` is a GLSL keyword; the generated struct would not compile.
// expect: static assertion failed: Texel::sample: the member's name is a reserved GLSL word; rename the member
#include <proceduray/shader/field_list.hpp>

namespace demo {
struct Texel {
  glm::vec4 sample;
};
PROCEDURAY_STRUCT(Texel, scalar, sample);
}  // namespace demo
