#include <examples/common/cli.hpp>
// @declarations
int usage(int argc, char** argv) {
  // @statements
  return 0;
}
