// What the paper scene's raygen and closest-hit shaders share: the TLAS and the ray range.
// The structs, the `constants` uniform and the constants radiance_ray, shadow_ray, ray_count,
// flag_* come from the generated declarations (paper_types.hpp), never from here.
#ifndef PAPER_GLSL
#define PAPER_GLSL

layout(set = 0, binding = 0) uniform accelerationStructureEXT tlas;

/// t_max of radiance rays: finite, since Vulkan need not honour IEEE infinities.
const float ray_far = 1.0e30;

#endif
