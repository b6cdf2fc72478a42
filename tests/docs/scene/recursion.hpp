#include "proceduray/scene/recursion.hpp"

// @declarations
void usage(const proceduray::Plan& plan) {
  // @statements
}
