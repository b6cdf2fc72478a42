// Proceduray: ray tracing of procedural geometry with Vulkan, in a few typed calls.
//
//   #include <proceduray/proceduray.hpp>
//   proceduray::vk::Context ctx;                       // GPU if present, else lavapipe
//   proceduray::Scene scene = make_scene();            // rays, objects, entries: examples/02_paper_scene
//   proceduray::vk::Renderer renderer(ctx, scene, options);   // compiles the scene, builds it on the device
//   auto blas = proceduray::vk::build_blas(ctx, geometries);   // or the thin layer alone: examples/01_hello_sphere
//
// Layers: scene/ (pure, no Vulkan) and shader/ (pure) under vk/ (the thin backend), and
// image/ for output. Each header also compiles on its own. Every exception the library throws
// is a proceduray::Error (error.hpp): catch (const proceduray::Error& e) reaches them all.
#pragma once

#include <proceduray/error.hpp>
#include <proceduray/image/png.hpp>
#include <proceduray/image/texture_data.hpp>
#include <proceduray/march/knobs.hpp>
#include <proceduray/march/primitives.hpp>
#include <proceduray/march/sphere_set.hpp>
#include <proceduray/march/calibration.hpp>
#include <proceduray/march/cut_planes.hpp>
#include <proceduray/march/metaballs.hpp>
#include <proceduray/mesh/obj.hpp>
#include <proceduray/scene/aabb_glsl.hpp>
#include <proceduray/scene/default_global_signature.hpp>
#include <proceduray/scene/distance_field.hpp>
#include <proceduray/scene/glsl_files.hpp>
#include <proceduray/scene/glsl_for.hpp>
#include <proceduray/scene/object.hpp>
#include <proceduray/scene/placement.hpp>
#include <proceduray/scene/quad_mesh.hpp>
#include <proceduray/scene/sbt_layout.hpp>
#include <proceduray/scene/sbt_printer.hpp>
#include <proceduray/scene/compile.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/scene/shader_context.hpp>
#include <proceduray/scene/world_origin.hpp>
#include <proceduray/shader/shader.hpp>
#include <proceduray/vk/acceleration.hpp>
#include <proceduray/vk/blas_input.hpp>
#include <proceduray/vk/buffer.hpp>
#include <proceduray/vk/context.hpp>
#include <proceduray/vk/descriptors.hpp>
#include <proceduray/vk/device_selection.hpp>
#include <proceduray/vk/error.hpp>
#include <proceduray/vk/frame_ring.hpp>
#include <proceduray/vk/handle.hpp>
#include <proceduray/vk/calibrate.hpp>
#include <proceduray/vk/measure.hpp>
#include <proceduray/vk/mesh_buffers.hpp>
#include <proceduray/vk/pipeline.hpp>
#include <proceduray/vk/pipeline_cache.hpp>
#include <proceduray/vk/renderer.hpp>
#include <proceduray/vk/sbt_buffer.hpp>
#include <proceduray/vk/texture.hpp>
#include <proceduray/vk/scene_acceleration.hpp>
#include <proceduray/vk/scene_instances.hpp>
#include <proceduray/vk/shader_compiler.hpp>
#include <proceduray/vk/spirv_cache.hpp>
#include <proceduray/version.hpp>
#include <proceduray/vk/storage_image.hpp>
#include <proceduray/vk/structs.hpp>
#include <proceduray/vk/timing.hpp>
#include <proceduray/vk/tlas.hpp>
#include <proceduray/vk/trace.hpp>
#include <proceduray/vk/vulkan_instance.hpp>
