#include <proceduray/march/sphere_set.hpp>
#include <proceduray/scene/scene.hpp>
#include "tests/docs/doc_types.hpp"
using DocScene = proceduray::Scene<doc_types::DocInterface>;
// @declarations
void usage(DocScene& scene) {
  // @statements
}
