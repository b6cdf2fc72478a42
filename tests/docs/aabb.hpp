#include <proceduray/aabb.hpp>
// @declarations
void usage() {
  // @statements
}
