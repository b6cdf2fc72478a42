// @skip-include <proceduray/implementation.hpp>
// The block is the whole of a .cpp file; in a batch with other headers it can only be read
// (implementation.hpp refuses to come after them), so nothing of it is compiled here.
#include <proceduray/config.hpp>
// @declarations
void usage() {
  // @statements
}
