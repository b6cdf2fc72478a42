// docs/guide/recursion.md's ```cpp block (the two example scenes traced from raygen).
#include "examples/02_paper_scene/paper_scene.hpp"
#include "examples/03_d3d12_scene/d3d12_scene.hpp"
// @declarations
void usage() {
  // @statements
}
