#include <proceduray/march/metaballs.hpp>
#include <proceduray/scene/scene.hpp>
// @declarations
void usage(proceduray::Scene& scene) {
  // @statements
}
