#include <examples/common/cli.hpp>
#include <CLI/CLI.hpp>  // the block adds an option of its own, as examples 03 and 04 do
// @declarations
int usage(int argc, char** argv) {
  // @statements
  return 0;
}
