// The GLSL declarations each shader of a scene needs, derived by compile(scene): nothing about
// payloads, attributes, records or bindings is written twice, and no device is involved, so a
// build step can write them to files (tools/glsl_for) as well as the renderer at run time.
//
//   const proceduray::Plan plan = proceduray::compile(scene);
//   std::string preamble = proceduray::glsl_for(plan, proceduray::ShaderStage::closest_hit, "shade.rchit");
//   std::string names = proceduray::glsl_summary(preamble);   // one line per name, no struct bodies
//
// What a shader gets (names are the convention the shaders use):
//   every stage   the structs of every registered type the scene uses; per ray type
//                 `const uint <ray>_ray`, `<ray>_flags` and `<ray>_mask` (its RayDesc), and
//                 `ray_count`; `layer_<name>` per layer; `<id>_callable` per callable; the
//                 `<geometry>_aabb_min`/`_max` of every procedural geometry (aabb_glsl.hpp); each
//                 named binding of the global signature (acceleration structure, rgba8 storage
//                 image, typed uniform, or a readonly storage buffer of T[] read as `<name>.data[i]`),
//                 and its named push constant block (`<name>.member`); the per-pixel output
//                 helpers output_t/normal/ids/steps/flags (outputs_glsl.hpp: empty macros for
//                 outputs not asked for), and output_hit(n) in closest-hit and any-hit stages;
//                 for each MeshRef<V> in root arguments, vertex(m, i), triangle_indices(m, prim) and
//                 interpolate(m, prim, barycentrics) (shader/mesh_ref.hpp)
//   tracing stages (raygen, miss, closest hit: the ones Vulkan lets trace)
//                 `rayPayloadEXT <Payload> <ray>` for every ray type, at location = ray index,
//                 and per ray type (when the global signature names an acceleration structure)
//                   void      trace_<ray>(vec3 origin, float tmin, vec3 direction, float tmax)
//                   <Payload> trace_<ray>(vec3 origin, float tmin, vec3 direction, float tmax, <Payload> p)
//                 which fill flags, mask, SBT offset and stride, miss index and payload location
//                 from the ray's declaration; the second copies p in and returns what the shaders
//                 left. A closest-hit shader has an outgoing payload of its own ray type too, so a
//                 reflection needs no save and restore of `payload`. A ray with no miss shader
//                 gets only the second (a miss returns p, never uninitialised memory). When the
//                 scene declares a recursion depth, a trace nested past it is skipped (the
//                 payload keeps what it held) and sets output_flag_depth: shaders that trace in
//                 a cycle cannot pass the pipeline's depth and crash the device.
//   calling stages (raygen, miss, closest hit, callable)
//                 `callableDataEXT <Data> <id>_data` per callable, at location = its index, and
//                   <Data> <id>_call(<Data> d)   (copies d in, executeCallableEXT, returns the data)
//   miss          `rayPayloadInEXT <Payload> payload` of the ray types it is the miss shader of
//   closest hit   `rayPayloadInEXT <Payload> payload` of the rays whose records use it, the
//                 group's `hitAttributeEXT <Attributes> hit`, the entries' `arguments` block (root arguments)
//   any hit       payload, hit and arguments as closest hit; no tracing, no callables
//   intersection  `hitAttributeEXT <Attributes> hit` and the entries' `arguments` block (root arguments)
//   callable      `callableDataInEXT <Data> call` of the callables it implements and their
//                 `arguments` block (root arguments); the other callables as above
// Incoming payloads and callable data sit at location ray_count (callable_count): past every
// outgoing one, so the two never overlap. A shader calling trace_<ray> for a ray the scene does
// not declare fails to compile, and the renderer's message names the ray and the declared ones.
// compile() throws SceneError when one shader is used in ways that need two different types
// (two payloads, attributes or record types), naming them: split the shader or unify the types.
// Every block comes from shader/glsl_codegen.hpp, the one GLSL emitter.
#pragma once

#include <proceduray/config.hpp>

#include "proceduray/scene/aabb_glsl.hpp"
#include "proceduray/scene/glsl_names.hpp"
#include "proceduray/scene/outputs_glsl.hpp"
#include "proceduray/scene/plan.hpp"
#include "proceduray/scene/scene.hpp"
#include "proceduray/shader/glsl_codegen.hpp"
#include "proceduray/shader/mesh_ref.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray {

namespace detail {

using proceduray::glsl_identifier;  // glsl_names.hpp

/// The one type a shader's uses agree on, or nullptr; throws when they disagree.
PROCEDURAY_DECL const TypeOps* one_type(const std::vector<const TypeOps*>& types, std::string_view shader, const char* what);

PROCEDURAY_DECL std::string binding_glsl(const Binding& b);

}  // namespace detail

namespace detail {

/// What every stage gets: the structs of every registered type, ray, layer and callable
/// constants, the named bindings and the push constant block.
PROCEDURAY_DECL std::string common_declarations(const detail::SceneCore& scene, const Plan& plan);

/// The record block of a shader whose records carry `types` (one type, or none).
PROCEDURAY_DECL std::string record_block(const std::vector<const TypeOps*>& types, std::string_view shader);

/// Outgoing callable data of every callable but `skip` (the one a callable shader receives), and
/// `<id>_call(d)` for each.
PROCEDURAY_DECL std::string callable_data(const detail::SceneCore& scene, std::uint32_t skip);

/// The name of the acceleration structure the trace functions trace: the global signature's
/// first named one, or "" (then there are no trace functions).
PROCEDURAY_DECL std::string trace_target(const Plan& plan);

/// The depth counter of a scene with a declared depth (Plan::depth_binding): its image, the
/// pipeline's depth, and proceduray_enter()/proceduray_leave() around each trace; "" without one.
PROCEDURAY_DECL std::string depth_counter(const Plan& plan, bool raygen);

/// What a tracing stage (raygen, miss, closest hit) gets: every ray's outgoing payload, at
/// location = ray index, and its trace functions (with the depth counter's checks).
PROCEDURAY_DECL std::string tracing_declarations(const detail::SceneCore& scene, const Plan& plan, bool raygen);

/// The root arguments type of a record, or nullptr.
PROCEDURAY_DECL const TypeOps* arguments_type(const detail::SceneCore& scene, const Plan& plan, const SbtRecord& record);

/// Payload, attributes, record and outgoing payloads of a hit-group stage.
PROCEDURAY_DECL std::string hit_declarations(const detail::SceneCore& scene, const Plan& plan, ShaderStage stage, std::string_view shader);

/// What `shader` as `stage` gets after the common declarations (see the top of this header);
/// compile() prepends common_declarations, the same for every stage, computed once.
PROCEDURAY_DECL std::string stage_declarations(const detail::SceneCore& scene, const Plan& plan, ShaderStage stage, std::string_view shader);

}  // namespace detail

/// The declarations compile() derived for `shader` as `stage`; throws UnknownIdError when the
/// plan has no such stage (a shader no entry uses, or the wrong stage).
PROCEDURAY_DECL const std::string& glsl_for(const Plan& plan, ShaderStage stage, std::string_view shader);

/// The names a shader's declarations give it, one line each: a struct as `struct T`, a block as
/// its header and instance name, a function as its signature, constants, variables and macros as
/// written. What `glsl_for` tools print (glsl_files_main --names), for a newcomer asking "what
/// can this shader call?".
PROCEDURAY_DECL std::string glsl_summary(std::string_view declarations);

}  // namespace proceduray

#include "proceduray/scene/glsl_for-inl.hpp"  // the bodies (config.hpp)
