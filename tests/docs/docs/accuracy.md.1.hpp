// docs/accuracy.md's ```cpp block (far from the origin: WorldOrigin).
#include <proceduray/scene/world_origin.hpp>
// @declarations
void usage(glm::dvec3 camera_eye, const glm::dmat4& world_from_object, glm::dvec3 new_eye, double pixel_angle,
           double nearest_t) {
  // @statements
  (void)t;
  (void)eye;
}
