// What the paper scene's raygen and closest-hit shaders share: the ray range. The structs,
// the bindings (tlas, image, constants), the ray indices (radiance_ray, shadow_ray,
// ray_count), the AABBs and the flag_* constants PaperScene declares come from the declarations
// glsl_for derives from the scene. Never from here.
#ifndef PAPER_GLSL
#define PAPER_GLSL

/// t_max of radiance rays: finite, since Vulkan need not honour IEEE infinities.
const float ray_far = 1.0e30;

#endif
