#include <proceduray/scene/geometry.hpp>
#include <proceduray/shader/field_list.hpp>

#include <vector>

// @declarations
void usage(const proceduray::TriangleMesh& mesh) {
  // @statements
}
