#include "tests/docs/scene/scene_names.hpp"
#include <proceduray/scene/shader_context.hpp>
using namespace doc_scene;

// @declarations
void usage(const DocScene& scene, const std::string& log) {
  // @statements
}
