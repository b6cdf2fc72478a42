#include "proceduray/scene/scene.hpp"

// @declarations
void usage(const proceduray::Scene& scene) {
  // @statements
}
