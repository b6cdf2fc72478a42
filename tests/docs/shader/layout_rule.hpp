#include <proceduray/shader/field_list.hpp>
struct Sphere { glm::vec3 center; float radius; };
// @declarations
void usage() {
  // @statements
}
