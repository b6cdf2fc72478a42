#include <proceduray/mesh/obj.hpp>
#include <proceduray/scene/scene.hpp>
// @declarations
void usage(proceduray::Scene& scene, std::size_t i) {
  // @statements
}
