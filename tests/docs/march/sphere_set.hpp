#include <proceduray/march/sphere_set.hpp>
#include <proceduray/scene/scene.hpp>
// @declarations
void usage(proceduray::Scene& scene) {
  // @statements
}
