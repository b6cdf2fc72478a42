#include <examples/common/paths.hpp>
#define PAPER_GLSL_DIR "generated"
// @declarations
int usage() {
  // @statements
  return 0;
}
