#include <proceduray/shader/camera.hpp>
// @declarations
void usage(std::uint32_t width, std::uint32_t height, glm::vec3 world_point) {
  // @statements
}
