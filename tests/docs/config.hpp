// @skip-include <proceduray/implementation.hpp>
// implementation.hpp must be the first Proceduray header of its file (it says so with #error), so
// in this batch only the header-only part of the block is compiled; examples/common/proceduray.cpp
// and tests/consumer build the other part.
#include <proceduray/config.hpp>
// @declarations
void usage() {
  // @statements
}
