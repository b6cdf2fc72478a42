#include <proceduray/image/png.hpp>
#include <cstdint>
#include <vector>
// @declarations
void usage(const std::vector<std::uint8_t>& rgba) {
  // @statements
}
