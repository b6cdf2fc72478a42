// The renderer: a scene compiled, built on the device, and traced. A thin composition of parts
// that are usable alone: SceneAcceleration (BLAS/TLAS and their updates), Bindings (descriptor
// sets, typed uniforms, storage buffers, push constants), make_scene_pipeline, SbtBuffer.
//
//   proceduray::vk::Renderer renderer(ctx, scene, {.shader_dirs = {"shaders"},
//                                                  .pipeline_cache = "proceduray.cache"});
//   renderer.set(constants_slot, constants);          // typed uniform, uploaded before the next trace
//   renderer.set_storage(tints_slot, tints);          // typed storage buffer (an array)
//   renderer.set_push(knobs_slot, knobs);             // typed push constants, recorded with the next trace
//   renderer.set_texture(ground_slot, ground);        // a TextureData (image/texture_data.hpp): mips, sampler
//   renderer.set_transform(pacman, 1, moved);         // DynamicTransform: TLAS refit, no BLAS work
//   renderer.set_visible(pacman, 0, false);           // hidden until shown again: a TLAS update
//   std::uint32_t i = renderer.add_instance(pacman, placed);   // any policy: a TLAS build; a handle
//   renderer.remove_instance(pacman, i);               // a TLAS build; i is refused from now on
//   renderer.set_aabbs(blob, {{box}});                 // DynamicGeometry: BLAS refit (or rebuild), TLAS update
//   proceduray::vk::Frame frame = renderer.render(1024, 768);
//   frame.rgba; frame.trace_ms;                       // pixels, GPU time of the trace
//
//   // The frame loop: N frames in flight (RendererOptions::frames_in_flight, default 2), nothing
//   // allocated per frame, pixels read only when asked, straight out of host-cached memory.
//   proceduray::vk::FrameTicket t = renderer.submit(1024, 768);    // records and submits; no wait
//   std::span<const std::uint8_t> rgba = renderer.rgba(t);        // waits; valid until N more submits
//   renderer.read_rgba(t, my_pixels);                              // or copies into your span
//   renderer.wait(t).trace_ms;                                     // times and work, no pixels
//   frame.outputs.t;                                  // per-pixel outputs the scene asked for (Scene::set_outputs)
//   frame.work.blas_builds;                           // what the frame rebuilt: BLAS builds, refits, TLAS work
//   ctx.submit([&](VkCommandBuffer cmd) { renderer.record(cmd, 1024, 768); });   // or into your own command buffer
//   renderer.image().read();                          // then read the image it traced into
//
// Its one input is a Plan (compile(scene), a value): built from a scene, it compiles it first;
// changing the scene afterwards does not change the renderer. It keeps a copy of the Context
// (a shared handle): the caller's may go first. A ticket names the renderer that issued it.
// Uniforms and push constants are recorded into each frame, so setting them never waits. The
// other setters write memory that submitted frames read: they wait for the frames in flight.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/scene/compile.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/vk/bindings.hpp>
#include <proceduray/vk/frame.hpp>
#include <proceduray/vk/frame_ring.hpp>
#include <proceduray/vk/mesh_buffers.hpp>
#include <proceduray/vk/field_knobs.hpp>
#include <proceduray/vk/output_images.hpp>
#include <proceduray/vk/sbt_buffer.hpp>
#include <proceduray/vk/scene_acceleration.hpp>
#include <proceduray/vk/scene_pipeline.hpp>
#include <proceduray/vk/storage_image.hpp>
#include <proceduray/vk/trace.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace proceduray::vk {

/// What building the renderer cost, in milliseconds of wall time.
struct BuildTimings {
  double acceleration_ms = 0;  ///< all BLAS builds and compactions, and the TLAS
  double compile_ms = 0;       ///< GLSL to SPIR-V (glslang)
  double pipeline_ms = 0;      ///< vkCreateRayTracingPipelinesKHR
  bool pipeline_cached = false;  ///< the pipeline cache file was valid and used
  std::uint32_t spirv_cached = 0;    ///< stages whose SPIR-V came from the cache (RendererOptions::cache)
  std::uint32_t spirv_compiled = 0;  ///< stages glslang compiled
  /// Pipelines built again for changed field knobs (RendererOptions::specialize_fields), and the
  /// wall time of all of them (pipeline and SBT).
  std::uint32_t rebuilds = 0;
  double rebuild_ms = 0;
};

/// Builds the device objects of a scene and traces frames of it.
class Renderer {
 public:
  /// Builds `plan` on `ctx`: the plan is all the renderer reads (geometry, records, stages,
  /// declarations, sizes); throws what Plan::layout() throws, and for shaders that fail.
  Renderer(const Context& ctx, proceduray::Plan plan, RendererOptions options = {});
  /// Compiles `scene` (compile.hpp) and builds its plan; the scene is not read afterwards.
  template <class Interface>
  Renderer(const Context& ctx, const proceduray::Scene<Interface>& scene, RendererOptions options = {})
      : Renderer(ctx, compile(scene), std::move(options)) {}
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  ~Renderer();  // out of line: a program compiles the parts' destruction once

  /// Sets a uniform's value; it is uploaded before the next trace. Other types do not compile.
  template <class T>
  void set(UniformSlot<T> slot, const std::type_identity_t<T>& value) {
    if (!m_bindings->has_buffer(slot)) m_ring->wait_all();  // the first set writes the descriptor set
    m_bindings->set(slot, value, "Renderer::set");
  }
  /// Sets a storage buffer's contents, an array of T (at least one element); reallocated when it grows.
  template <class T>
  void set_storage(StorageSlot<T> slot, std::span<const std::type_identity_t<T>> values) {
    m_ring->wait_all();  // written in place (and maybe reallocated): no frame in flight may read it
    m_bindings->set_storage(slot, values, "Renderer::set_storage");
  }
  /// Uploads a texture (with its mips, per `sampler`) into element `index` of a TextureSlot; throws
  /// UsageError for a bad index or a cube map for a 2D slot (and the reverse), DeviceLimitError
  /// for a size past the device's limit. Waits for the frames in flight.
  void set_texture(const TextureSlot& slot, const TextureData& data, const SamplerDesc& sampler = {},
                   std::uint32_t index = 0) {
    m_ring->wait_all();  // the descriptor set is written in place
    m_bindings->set_texture(slot, index, data, sampler, "Renderer::set_texture");
  }
  /// Sets the push constants, recorded with the next trace. Other types do not compile; a slot of
  /// another type than the global signature's throws.
  template <class T>
  void set_push(PushConstantSlot<T> slot, const std::type_identity_t<T>& value) {
    m_bindings->set_push(slot, value, "Renderer::set_push");
  }
  /// Moves instance `instance` of `geometry`; the TLAS is refit before the next trace (no BLAS work).
  /// Throws for a Static geometry (declare it UpdatePolicy::DynamicTransform).
  void set_transform(GeometryId geometry, std::uint32_t instance, const glm::mat4& object_to_world) {
    m_ring->wait_all();
    m_structures->set_transform(geometry, instance, object_to_world, "Renderer::set_transform");
  }
  /// Moves every instance of `geometry` (one matrix per instance, in instance order): one TLAS
  /// refit for all of them. Throws like set_transform, or for a count that is not the instance count.
  void set_transforms(GeometryId geometry, std::span<const glm::mat4> object_to_world) {
    m_ring->wait_all();
    m_structures->set_transforms(geometry, object_to_world, "Renderer::set_transforms");
  }
  /// Changes one instance's mask (Layers bits), any policy: a TLAS build before the next trace.
  /// Throws UsageError for a mask over 0xFF (an instance mask has 8 bits).
  void set_mask(GeometryId geometry, std::uint32_t instance, std::uint32_t mask) {
    m_ring->wait_all();
    m_structures->set_mask(geometry, instance, mask, "Renderer::set_mask");
  }
  /// Hides or shows one instance, any policy: a TLAS update, never a rebuild (Unity's "Off").
  void set_visible(GeometryId geometry, std::uint32_t instance, bool visible) {
    m_ring->wait_all();
    m_structures->set_visible(geometry, instance, visible, "Renderer::set_visible");
  }
  /// Adds an instance of `geometry` (of its BLAS: every geometry sharing it), any policy, with the
  /// hit records of the geometry's instances without entries of their own; no other instance's SBT
  /// offset changes. A TLAS build before the next trace. Returns its handle (SceneInstances: a slot
  /// and a generation; a removed instance's slot is reused). Its gl_InstanceCustomIndexEXT is a
  /// removed instance's, else one past every custom index so far, so a per-instance storage buffer
  /// must hold that many elements first (else UsageError).
  std::uint32_t add_instance(GeometryId geometry, const glm::mat4& object_to_world, std::uint32_t mask = 0xFF);
  /// Removes one instance: a TLAS build. Its handle is refused from now on (UsageError), also once
  /// its slot holds a new instance.
  void remove_instance(GeometryId geometry, std::uint32_t instance) {
    m_ring->wait_all();
    m_structures->remove_instance(geometry, instance, "Renderer::remove_instance");
  }
  /// The handles of the instances `geometry` has now, in slot order.
  std::vector<std::uint32_t> instances(GeometryId geometry) const {
    return m_structures->instances().instances(geometry, "Renderer::instances");
  }
  /// Replaces a DynamicGeometry procedural geometry's boxes: the same count refits its BLAS before
  /// the next trace, another count rebuilds it. Throws for other policies, triangles or bad boxes.
  void set_aabbs(GeometryId geometry, std::span<const Aabb> boxes) {
    m_ring->wait_all();
    m_structures->set_aabbs(geometry, boxes, "Renderer::set_aabbs");
  }
  /// Replaces a DynamicGeometry triangle geometry's vertex positions (same count, same indices): BLAS refit.
  void set_vertices(GeometryId geometry, std::span<const glm::vec3> vertices) {
    m_ring->wait_all();
    m_structures->set_vertices(geometry, vertices, "Renderer::set_vertices");
  }
  /// Replaces a DynamicGeometry triangle geometry's mesh: refit when the indices are the same, else rebuild.
  void set_mesh(GeometryId geometry, TriangleMesh mesh) {
    m_ring->wait_all();
    m_structures->set_mesh(geometry, std::move(mesh), "Renderer::set_mesh");
  }

  /// Radians per pixel of the view (Camera::pixel_angle): distance fields' footprint thresholds
  /// scale with it, so a scene with fields needs it before its first frame (else UsageError).
  void set_pixel_angle(float radians) { m_fields->set_pixel_angle(radians, "Renderer::set_pixel_angle"); }
  /// Sets a distance field's knobs (add_distance_field's geometry), checked against what it
  /// accepts (field_capabilities); used from the next frame on. With specialized fields (the
  /// default) a change builds the pipeline and SBT again before that frame (timings().rebuilds).
  void set_field_knobs(GeometryId field, const MarchKnobs& knobs) {
    m_fields->set(field, knobs, "Renderer::set_field_knobs");
  }
  /// A distance field's knobs now (its capabilities' defaults until set).
  const MarchKnobs& field_knobs(GeometryId field) const { return m_fields->get(field, "Renderer::field_knobs"); }

  /// Traces one width x height frame, waits for it and, with `readback`, returns its pixels and
  /// outputs (copied into the Frame's vectors: the frame loop reads them with submit and rgba).
  Frame render(std::uint32_t width, std::uint32_t height, bool readback = true);
  /// Records and submits one width x height frame, with the copies `readback` asks for, and
  /// returns at once: it waits only for the frame that used the slot frames_in_flight frames ago.
  FrameTicket submit(std::uint32_t width, std::uint32_t height, Readback readback = Readback::rgba);
  /// The context this renderer made its objects from: a copy of the one it was given, sharing its device.
  const Context& context() const noexcept { return m_ctx; }
  /// The number this renderer's tickets carry (FrameTicket::renderer), unique in the process.
  std::uint64_t serial() const { return m_serial; }
  /// Waits for the frame; its times and structure work (its rgba and outputs vectors stay empty).
  /// Throws UsageError for a frame whose slot a later frame reused.
  Frame wait(FrameTicket frame);
  /// Waits for the frame and views its RGBA8 pixels (width * height * 4 bytes, rows top to bottom)
  /// in mapped host-cached memory, valid until frames_in_flight more frames are submitted. Throws
  /// UsageError for a frame submitted without readback or whose slot was reused.
  std::span<const std::uint8_t> rgba(FrameTicket frame);
  /// Waits for the frame and copies its pixels into `out`; throws UsageError when `out` holds
  /// fewer than width * height * 4 bytes (or as rgba()).
  void read_rgba(FrameTicket frame, std::span<std::uint8_t> out);
  /// Waits for the frame (submitted with Readback::all) and views one per-pixel output: float for
  /// t and normal, std::uint32_t for ids, steps and flags (as in Outputs).
  template <class T>
  std::span<const T> output(FrameTicket frame, Output which) {
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, std::uint32_t>,
                  "Renderer::output: outputs are float (t, normal) or std::uint32_t (ids, steps, flags)");
    const bool is_float = which == Output::t || which == Output::normal;
    if (is_float != std::is_same_v<T, float>) {
      throw UsageError(std::string("Renderer::output: output '") + std::string(proceduray::name(which)) + "' holds " +
                       (is_float ? "float" : "std::uint32_t") + " values; ask for output<" +
                       (is_float ? "float" : "std::uint32_t") + ">");
    }
    const std::span<const std::uint8_t> bytes = output_bytes(frame, which, "Renderer::output");
    return {reinterpret_cast<const T*>(bytes.data()), bytes.size() / sizeof(T)};
  }
  /// Frames in flight, as RendererOptions::frames_in_flight asked.
  std::uint32_t frames_in_flight() const noexcept { return m_ring->size(); }
  /// Records one width x height frame into a command buffer the caller submits: the structure
  /// work the updates need, then the trace into image(). Changed uniforms are uploaded now, so
  /// submit before the next set(). Returns the structure work recorded.
  FrameWork record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height);
  /// Traces a small frame so lazy work (lavapipe compiles shaders at the first trace) is out of
  /// timed frames; returns its wall time in ms.
  double warm_up();

  const BuildTimings& timings() const noexcept { return m_timings; }
  /// The pipeline and SBT of the last frame (a knob change replaces both: don't keep them).
  const Pipeline& pipeline() const noexcept { return *m_pipeline; }
  const SbtBuffer& sbt() const noexcept { return *m_sbt; }
  const Tlas& tlas() const noexcept { return m_structures->tlas(); }
  /// The image the last frame traced into; throws before the first frame.
  const StorageImage& image() const;
  /// What compile(scene) derived: records, instances, pipeline plan, declarations.
  const proceduray::Plan& plan() const noexcept { return m_plan; }
  /// Bytes of every BLAS (Static ones after compaction).
  VkDeviceSize blas_bytes() const noexcept { return m_structures->blas_bytes(); }

 private:
  using Clock = std::chrono::steady_clock;
  static double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }
  /// Checks the size and the bindings, and makes the image when the size changed.
  void prepare(std::uint32_t width, std::uint32_t height, std::string_view op);
  FrameTicket submit_as(std::uint32_t width, std::uint32_t height, Readback readback, std::string_view op);
  /// Records one of the ring's timestamps (or nothing) around vkCmdTraceRaysKHR.
  struct Stamp {
    const FrameRing* ring = nullptr;
    const FrameSlot* slot = nullptr;
    std::uint32_t which = 0;
    void operator()(VkCommandBuffer) const { if (ring != nullptr) ring->stamp(*slot, which); }
  };
  /// Per slot: what its frame was asked and what it did.
  struct SlotFrame {
    Frame frame;
    Readback readback = Readback::none;
    bool timed = false;  // trace_ms read after the wait
    Clock::time_point submitted{};
  };
  /// The image layout transitions, structure work, uploads and the trace.
  FrameWork record_frame(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, Stamp before, Stamp after);
  /// The pipeline and SBT for the fields' knobs now (specialized) or for any (general).
  void build_pipeline(PipelineTimings* timings);
  /// The slot of `frame`, waited for and timed.
  std::pair<FrameSlot*, SlotFrame*> finished(FrameTicket frame, std::string_view op);
  /// Throws UsageError, naming `op`, for a ticket another renderer (or no submit()) issued.
  void check_ticket(FrameTicket frame, std::string_view op) const;
  /// Mapped bytes of output `which` in a slot (Readback::all), after its rgba.
  std::span<const std::uint8_t> output_bytes(FrameTicket frame, Output which, std::string_view op);

  /// A number no other renderer of this process has: what its tickets carry.
  static std::uint64_t next_serial() {
    static std::atomic<std::uint64_t> last{0};
    return ++last;
  }

  std::uint64_t m_serial = next_serial();
  Context m_ctx;  // a copy, first: destroyed after every object made from it (the device outlives them)
  RendererOptions m_options;
  proceduray::Plan m_plan;
  SceneStages m_stages;                 // kept only while a knob change may rebuild the pipeline
  std::uint64_t m_pipeline_knobs = 0;   // FieldKnobs::version() the pipeline was specialized for
  SbtLayout m_layout;
  BuildTimings m_timings;
  std::unique_ptr<SceneAcceleration> m_structures;
  std::unique_ptr<Bindings> m_bindings;
  std::unique_ptr<Pipeline> m_pipeline;
  std::unique_ptr<MeshBuffers> m_meshes;  // the vertex and triangle buffers MeshRefs in m_sbt point at
  std::unique_ptr<SbtBuffer> m_sbt;
  std::unique_ptr<StorageImage> m_image;
  std::unique_ptr<OutputImages> m_outputs;
  std::unique_ptr<FieldKnobs> m_fields;
  std::vector<SlotFrame> m_slot_frames;  // index = FrameSlot::index
  std::unique_ptr<FrameRing> m_ring;     // last: destroyed first, it waits for the frames in flight
};

}  // namespace proceduray::vk

#include "proceduray/vk/renderer-inl.hpp"  // the bodies (config.hpp)
