// What the D3D12 scene's shaders share beyond the derived declarations (structs, tlas, image,
// constants, radiance_ray, shadow_ray, ray_count, and the flag_* constants the scene declares).
#ifndef D3D12_GLSL
#define D3D12_GLSL

/// t_max of radiance rays: finite, since Vulkan need not honour IEEE infinities.
const float ray_far = 1.0e30;

bool nonfinite3(vec3 v) { return any(isnan(v)) || any(isinf(v)); }

#endif
