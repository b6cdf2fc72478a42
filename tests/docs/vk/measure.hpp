#include "tests/docs/vk/vk_names.hpp"
#include <proceduray/vk/measure.hpp>
using namespace doc_vk;
namespace mine {
template <class T>
struct gyroid {  // what a class template including gyroid.glsl gives (shader/glsl_cpp.hpp)
  static T gyroid_distance(glm::vec<3, T> p) { return glm::length(p) - T(1); }
};
}  // namespace mine

// @declarations
void usage(const proceduray::vk::Context& ctx) {
  // @statements
}
