// Primary rays of proceduray::Camera (include/proceduray/shader/camera.hpp). Needs the
// generated declaration of struct Camera before it.
//
//   vec3 dir = camera_ray(constants.camera, gl_LaunchIDEXT.xy, gl_LaunchSizeEXT.xy);
//   traceRayEXT(..., constants.camera.eye.xyz, 0.0, dir, ...);
#ifndef PROCEDURAY_COMMON_CAMERA_GLSL
#define PROCEDURAY_COMMON_CAMERA_GLSL

vec3 camera_ray(Camera camera, uvec2 pixel, uvec2 size) {
  vec2 uv = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
  return normalize(camera.forward.xyz + uv.x * camera.right.xyz - uv.y * camera.up.xyz);
}

#endif
