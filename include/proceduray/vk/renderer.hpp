// The renderer: a scene compiled, built on the device, and traced. A thin composition of parts
// that are usable alone: SceneAcceleration (BLAS/TLAS and their updates), Bindings (descriptor
// sets, typed uniforms, storage buffers, push constants), make_scene_pipeline, SbtBuffer.
//
//   proceduray::vk::Renderer renderer(ctx, scene, {.shader_dirs = {"shaders"},
//                                                  .pipeline_cache = "proceduray.cache"});
//   renderer.set(constants_slot, constants);          // typed uniform, uploaded before the next trace
//   renderer.set_storage(tints_slot, tints);          // typed storage buffer (an array)
//   renderer.set_push(knobs_slot, knobs);             // typed push constants, recorded with the next trace
//   renderer.set_transform(pacman, 1, moved);         // DynamicTransform: TLAS refit, no BLAS work
//   renderer.set_aabbs(blob, {{box}});                 // DynamicGeometry: BLAS refit (or rebuild), TLAS update
//   proceduray::vk::Frame frame = renderer.render(1024, 768);
//   frame.rgba; frame.trace_ms;                       // pixels, GPU time of the trace
//   frame.outputs.t;                                  // per-pixel outputs the scene asked for (Scene::set_outputs)
//   frame.work.blas_builds;                           // what the frame rebuilt: BLAS builds, refits, TLAS work
//   ctx.submit([&](VkCommandBuffer cmd) { renderer.record(cmd, 1024, 768); });   // or into your own command buffer
//   renderer.image().read();                          // then read the image it traced into
//
// It compiles the scene (compile.hpp) and keeps the Plan, a value: changing the scene afterwards
// does not change the renderer; the scene is read only while the constructor runs.
#pragma once

#include <proceduray/scene/compile.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/vk/bindings.hpp>
#include <proceduray/vk/frame.hpp>
#include <proceduray/vk/output_images.hpp>
#include <proceduray/vk/sbt_buffer.hpp>
#include <proceduray/vk/scene_acceleration.hpp>
#include <proceduray/vk/scene_pipeline.hpp>
#include <proceduray/vk/storage_image.hpp>
#include <proceduray/vk/trace.hpp>

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace proceduray::vk {

/// What building the renderer cost, in milliseconds of wall time.
struct BuildTimings {
  double acceleration_ms = 0;  ///< all BLAS builds and compactions, and the TLAS
  double compile_ms = 0;       ///< GLSL to SPIR-V (glslang)
  double pipeline_ms = 0;      ///< vkCreateRayTracingPipelinesKHR
  bool pipeline_cached = false;  ///< the pipeline cache file was valid and used
};

/// Builds the device objects of a scene and traces frames of it.
class Renderer {
 public:
  /// Compiles `scene` and builds it on `ctx`; throws what compile() and Plan::layout() throw.
  Renderer(const Context& ctx, const proceduray::Scene& scene, RendererOptions options = {});
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Sets a uniform's value; it is uploaded before the next trace. Other types do not compile.
  template <class T>
  void set(UniformSlot<T> slot, const std::type_identity_t<T>& value) {
    m_bindings->set(slot, value, "Renderer::set");
  }
  /// Sets a storage buffer's contents, an array of T (at least one element); reallocated when it grows.
  template <class T>
  void set_storage(StorageSlot<T> slot, std::span<const std::type_identity_t<T>> values) {
    m_bindings->set_storage(slot, values, "Renderer::set_storage");
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
    m_structures->set_transform(geometry, instance, object_to_world, "Renderer::set_transform");
  }
  /// Moves every instance of `geometry` (one matrix per instance, in instance order): one TLAS
  /// refit for all of them. Throws like set_transform, or for a count that is not the instance count.
  void set_transforms(GeometryId geometry, std::span<const glm::mat4> object_to_world) {
    m_structures->set_transforms(geometry, object_to_world, "Renderer::set_transforms");
  }
  /// Changes the instance mask (Layers bits) of one instance, any policy: the TLAS is rebuilt
  /// before the next trace (a mask is not a motion, so no refit is involved).
  /// Throws UsageError for a mask over 0xFF (an instance mask has 8 bits).
  void set_mask(GeometryId geometry, std::uint32_t instance, std::uint32_t mask) {
    m_structures->set_mask(geometry, instance, mask, "Renderer::set_mask");
  }
  /// Replaces a DynamicGeometry procedural geometry's boxes: the same count refits its BLAS before
  /// the next trace, another count rebuilds it. Throws for other policies, triangles or bad boxes.
  void set_aabbs(GeometryId geometry, std::span<const Aabb> boxes) {
    m_structures->set_aabbs(geometry, boxes, "Renderer::set_aabbs");
  }
  /// Replaces a DynamicGeometry triangle geometry's vertex positions (same count, same indices): BLAS refit.
  void set_vertices(GeometryId geometry, std::span<const glm::vec3> vertices) {
    m_structures->set_vertices(geometry, vertices, "Renderer::set_vertices");
  }
  /// Replaces a DynamicGeometry triangle geometry's mesh: refit when the indices are the same, else rebuild.
  void set_mesh(GeometryId geometry, TriangleMesh mesh) { m_structures->set_mesh(geometry, std::move(mesh), "Renderer::set_mesh"); }

  /// Traces one width x height frame and, with `readback`, returns its pixels.
  Frame render(std::uint32_t width, std::uint32_t height, bool readback = true);
  /// Records one width x height frame into a command buffer the caller submits: the structure
  /// work the updates need, then the trace into image(). Changed uniforms are uploaded now, so
  /// submit before the next set(). Returns the structure work recorded.
  FrameWork record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height);
  /// Traces a small frame so lazy work (lavapipe compiles shaders at the first trace) is out of
  /// timed frames; returns its wall time in ms.
  double warm_up();

  const BuildTimings& timings() const noexcept { return m_timings; }
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
  /// The structure work and the trace, with `stamp(cmd, 0)` and `stamp(cmd, 1)` around vkCmdTraceRaysKHR.
  FrameWork record_frame(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height,
                         const std::function<void(VkCommandBuffer, std::uint32_t)>& stamp);

  const Context* m_ctx;
  proceduray::Plan m_plan;
  SbtLayout m_layout;
  BuildTimings m_timings;
  std::unique_ptr<SceneAcceleration> m_structures;
  std::unique_ptr<Bindings> m_bindings;
  std::unique_ptr<Pipeline> m_pipeline;
  std::unique_ptr<SbtBuffer> m_sbt;
  std::unique_ptr<StorageImage> m_image;
  std::unique_ptr<OutputImages> m_outputs;
  DeviceHandle<VkQueryPool> m_queries;
};

// ---------------------------------------------------------------------------------------------

inline Renderer::Renderer(const Context& ctx, const proceduray::Scene& scene, RendererOptions options)
    : m_ctx(&ctx), m_plan(compile(scene)), m_layout(m_plan.layout(ctx.limits())) {
  if (const auto raygen = m_plan.records(SbtRegionKind::raygen); raygen.size() > 1) {
    throw UsageError("Renderer: the scene has " + std::to_string(raygen.size()) + " raygen entries (first \"" +
                     m_plan.pipeline().groups[raygen[0].group].name + "\", second \"" +
                     m_plan.pipeline().groups[raygen[1].group].name + "\"); a Renderer traces one raygen: keep "
                     "one per scene, or make one scene per raygen");
  }
  const auto start = Clock::now();
  m_structures = std::make_unique<SceneAcceleration>(ctx, scene, m_plan, options.blas);
  m_timings.acceleration_ms = ms_since(start);
  m_bindings = std::make_unique<Bindings>(ctx, m_plan.global_signature(), m_structures->tlas().structure(),
                                          static_cast<std::uint32_t>(m_plan.instances().size()));
  PipelineTimings pipeline;
  m_pipeline = make_scene_pipeline(ctx, m_plan, m_bindings->layouts(), m_bindings->push_size(), std::move(options),
                                   &pipeline);
  m_timings.compile_ms = pipeline.compile_ms;
  m_timings.pipeline_ms = pipeline.pipeline_ms;
  m_timings.pipeline_cached = pipeline.pipeline_cached;
  m_sbt = std::make_unique<SbtBuffer>(ctx, *m_pipeline, m_plan, m_layout);
  m_outputs = std::make_unique<OutputImages>(ctx, m_plan.outputs());
  if (ctx.timestamp_period_ns() > 0) {
    auto info = make<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2;
    VkQueryPool pool = VK_NULL_HANDLE;
    check(vkCreateQueryPool(ctx.device(), &info, nullptr, &pool), "vkCreateQueryPool");
    m_queries = own(ctx.device(), pool, vkDestroyQueryPool);
  }
}

inline void Renderer::prepare(std::uint32_t width, std::uint32_t height, std::string_view op) {
  check_trace_size(*m_ctx, width, height);
  m_bindings->check_ready(op);
  m_outputs->resize(width, height, *m_bindings);
  if (m_image && m_image->width() == width && m_image->height() == height) return;
  m_image = std::make_unique<StorageImage>(*m_ctx, width, height);
  m_bindings->bind_image(m_image->view());
}

inline FrameWork Renderer::record_frame(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height,
                                        const std::function<void(VkCommandBuffer, std::uint32_t)>& stamp) {
  const FrameWork work = m_structures->record(cmd);  // each structure build ends with a barrier for the trace
  m_bindings->upload();
  m_outputs->record_clear(cmd);
  record_trace(*m_ctx, cmd, *m_pipeline, m_bindings->sets(), *m_sbt, width, height, m_bindings->push(),
               std::function<void(VkCommandBuffer)>([&](VkCommandBuffer c) { stamp(c, 0); }),
               std::function<void(VkCommandBuffer)>([&](VkCommandBuffer c) { stamp(c, 1); }));
  return work;
}

inline FrameWork Renderer::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) {
  prepare(width, height, "Renderer::record");
  return record_frame(cmd, width, height, [](VkCommandBuffer, std::uint32_t) {});
}

inline Frame Renderer::render(std::uint32_t width, std::uint32_t height, bool readback) {
  prepare(width, height, "Renderer::render");
  Frame frame{width, height, {}, 0, 0, false, {}, {}};
  const VkQueryPool queries = m_queries.get();
  const auto host_start = Clock::now();
  const auto wall_start = host_start;
  m_ctx->submit([&](VkCommandBuffer cmd) {
    if (queries != VK_NULL_HANDLE) vkCmdResetQueryPool(cmd, queries, 0, 2);
    frame.work = record_frame(cmd, width, height, [&](VkCommandBuffer c, std::uint32_t query) {
      if (queries == VK_NULL_HANDLE) return;
      vkCmdWriteTimestamp(c, query == 0 ? VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT : VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT,
                          queries, query);
    });
    frame.host_ms = ms_since(host_start);
  });
  frame.tlas_refit = frame.work.tlas_builds + frame.work.tlas_updates > 0;
  if (queries != VK_NULL_HANDLE) {
    std::uint64_t stamps[2] = {};
    check(vkGetQueryPoolResults(m_ctx->device(), queries, 0, 2, sizeof stamps, stamps, sizeof stamps[0],
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults", "trace timestamps");
    frame.trace_ms = static_cast<double>(stamps[1] - stamps[0]) * m_ctx->timestamp_period_ns() * 1e-6;
  } else {
    frame.trace_ms = ms_since(wall_start);
  }
  if (readback) {
    frame.rgba = m_image->read();
    frame.outputs = m_outputs->read();
  }
  return frame;
}

inline const StorageImage& Renderer::image() const {
  if (!m_image) throw UsageError("Renderer::image: no frame was traced yet; call render() or record() first");
  return *m_image;
}

inline double Renderer::warm_up() {
  const auto start = Clock::now();
  render(8, 8, false);
  return ms_since(start);
}

}  // namespace proceduray::vk
