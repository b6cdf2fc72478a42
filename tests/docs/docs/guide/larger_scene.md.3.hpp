// docs/guide/larger_scene.md's third ```cpp block (the build-time generator of example 02).
#include <proceduray/scene/glsl_files.hpp>
#include "tests/docs/doc_types.hpp"
namespace paper {
struct PaperScene : proceduray::Scene<doc_types::DocInterface> {};
}  // namespace paper
// @declarations
void usage() {
  // @statements
}
