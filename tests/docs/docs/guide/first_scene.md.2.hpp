// docs/guide/first_scene.md's second ```cpp block (the interface): the structs as the first scene declares them.
#include "tests/docs/docs/first_scene_names.hpp"
namespace pr = proceduray;
using doc_first_scene::Colour;
using doc_first_scene::BallHit;
using doc_first_scene::Paint;
using doc_first_scene::Constants;
// @declarations
void usage() {
  // @statements
  static_assert(std::is_same_v<Interface, doc_first_scene::Interface>);
}
