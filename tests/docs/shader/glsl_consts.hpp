#include <proceduray/shader/glsl_consts.hpp>
#include <cstdint>
#include <string>
// @declarations
void usage() {
  // @statements
}
