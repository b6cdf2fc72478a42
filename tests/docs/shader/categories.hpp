#include <proceduray/shader/shader.hpp>
#include "tests/docs/doc_types.hpp"
using namespace doc_types;

// @declarations
void usage() {
  // @statements
}
