// docs/guide/first_scene.md's first ```cpp block (a struct and its registration).
#include <proceduray/proceduray.hpp>
// @declarations
void usage() {
  // @statements
}
