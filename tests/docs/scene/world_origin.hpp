#include <proceduray/scene/world_origin.hpp>

// @declarations
void usage(glm::dvec3 camera_eye, const glm::dmat4& world_from_object, glm::vec3 hit_point, double footprint) {
  // @statements
  (void)t;
  (void)eye;
  (void)hit;
}
