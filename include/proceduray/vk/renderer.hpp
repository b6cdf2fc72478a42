// The renderer: everything a built shader table implies, made on the device, and frames traced.
//
//   proceduray::ShaderBindingTable sbt = table.build(ctx.limits());
//   proceduray::vk::Renderer renderer(ctx, sbt, {.shader_dirs = {"shaders"},
//                                                .pipeline_cache = "proceduray.cache"});
//   renderer.set(constants_slot, constants);          // typed uniform, uploaded before the next trace
//   renderer.set_storage(tints_slot, tints);          // typed storage buffer (an array)
//   renderer.set_push(knobs_slot, knobs);             // typed push constants, recorded with the next trace
//   renderer.set_transform(pacman, 1, moved);         // DynamicTransform: TLAS refit, no BLAS work
//   renderer.set_aabbs(blob, {{box}});                 // DynamicGeometry: BLAS refit (or rebuild), TLAS update
//   proceduray::vk::Frame frame = renderer.render(1024, 768);
//   frame.rgba; frame.trace_ms;                       // pixels, GPU time of the trace
//   frame.work.blas_builds;                           // what the frame rebuilt: BLAS builds, refits, TLAS work
//
// From the table it makes: one BLAS per scene BLAS (triangles or AABBs; compacted when Static,
// kept refittable when DynamicGeometry), a TLAS whose instances carry the SBT offsets and masks
// the scene assigned (refittable when any geometry is dynamic), descriptor sets
// from the global signature (the acceleration-structure binding gets the TLAS, the storage
// image binding the frame, uniform bindings the values given with set()), the pipeline from
// the plan (shaders read from shader_dirs, compiled with the declarations glsl_for derives, the
// stack size from the groups' own sizes, a disk cache when asked), and the SBT bytes.
// The table and its scene must outlive the renderer.
//
// Errors are proceduray::Error (error.hpp): a bad matrix, box or instance index given to set_*
// throws InvalidGeometryError naming the call, the geometry and the instance; a closest-hit (or
// other non-raygen) shader that traces rays at an undeclared depth throws UsageError at
// construction (ShaderTable::set_max_recursion_depth); a limit of the device, DeviceLimitError.
#pragma once

#include <proceduray/scene/glsl_for.hpp>
#include <proceduray/scene/shader_binding_table.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/vk/acceleration.hpp>
#include <proceduray/vk/descriptors.hpp>
#include <proceduray/vk/pipeline.hpp>
#include <proceduray/vk/pipeline_cache.hpp>
#include <proceduray/vk/refittable_blas.hpp>
#include <proceduray/vk/sbt_buffer.hpp>
#include <proceduray/vk/storage_image.hpp>
#include <proceduray/vk/trace.hpp>

#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace proceduray::vk {

/// How a Renderer finds and compiles its shaders. Every member has a default.
struct RendererOptions {
  std::vector<std::filesystem::path> shader_dirs;  ///< where the plan's shader names are read; default: the current folder
  /// GLSL every shader gets after the generated declarations (glsl_for): the scene's own constants, say.
  std::string extra_declarations;
  /// Replaces the generated declarations when set: the whole preamble of each shader.
  std::function<std::string(ShaderStage, const std::string& name)> declarations;
  std::filesystem::path pipeline_cache;  ///< cache file; empty (default): none
  BuildOptions blas{};                   ///< BLAS builds; default compacted, fast trace
};

/// What building the renderer cost, in milliseconds of wall time.
struct BuildTimings {
  double acceleration_ms = 0;  ///< all BLAS builds and compactions, and the TLAS
  double compile_ms = 0;       ///< GLSL to SPIR-V (glslang)
  double pipeline_ms = 0;      ///< vkCreateRayTracingPipelinesKHR
  bool pipeline_cached = false;  ///< the pipeline cache file was valid and used
};

/// Acceleration-structure work a frame did before its trace, as the update policies allowed.
struct FrameWork {
  std::uint32_t blas_builds = 0;   ///< DynamicGeometry BLASes rebuilt (topology changed)
  std::uint32_t blas_refits = 0;   ///< DynamicGeometry BLASes refit in place
  std::uint32_t tlas_builds = 0;   ///< TLAS rebuilt (a BLAS it references was rebuilt)
  std::uint32_t tlas_updates = 0;  ///< TLAS refit (instances moved or a BLAS was refit)
  friend bool operator==(const FrameWork&, const FrameWork&) = default;
};

/// One traced frame.
struct Frame {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> rgba;  ///< width * height RGBA8 pixels, rows top to bottom; empty without readback
  double trace_ms = 0;  ///< GPU time between timestamps around vkCmdTraceRaysKHR (wall time if the queue has none)
  double host_ms = 0;   ///< host work before submit: uniform uploads, BLAS input and TLAS instance writes, recording
  bool tlas_refit = false;  ///< the frame refit or rebuilt the TLAS (work.tlas_updates + work.tlas_builds > 0)
  FrameWork work;           ///< acceleration-structure work done for this frame
};

/// Builds the device objects of a shader table and traces frames of it.
class Renderer {
 public:
  Renderer(const Context& ctx, const proceduray::ShaderBindingTable& table, RendererOptions options = {});
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Sets a uniform's value; it is uploaded before the next trace. Other types do not compile.
  template <class T>
  void set(UniformSlot<T> slot, const std::type_identity_t<T>& value) {
    Uniform& u = uniform(slot.set, slot.binding, sizeof(T), "Renderer::set");
    std::memcpy(u.value.data(), &value, sizeof(T));
    u.dirty = true;
  }
  /// Sets a storage buffer's contents, an array of T (at least one element); reallocated when it grows.
  template <class T>
  void set_storage(StorageSlot<T> slot, std::span<const std::type_identity_t<T>> values) {
    set_storage_bytes(slot.set, slot.binding, std::as_bytes(values), "Renderer::set_storage");
  }
  /// Sets the push constants, recorded with the next trace. Other types do not compile; a slot of
  /// another type than the global signature's throws.
  template <class T>
  void set_push(PushConstantSlot<T> slot, const std::type_identity_t<T>& value) {
    set_push_bytes(slot, &type_ops<T>, std::as_bytes(std::span<const T>(&value, 1)));
  }
  /// Moves instance `instance` of `geometry`; the TLAS is refit before the next trace (no BLAS work).
  /// Throws for a Static geometry (declare it UpdatePolicy::DynamicTransform).
  void set_transform(GeometryId geometry, std::uint32_t instance, const glm::mat4& object_to_world);
  /// Moves every instance of `geometry` (one matrix per instance, in instance order): one TLAS
  /// refit for all of them. Throws like set_transform, or for a count that is not the instance count.
  void set_transforms(GeometryId geometry, std::span<const glm::mat4> object_to_world);
  /// Changes the instance mask (Layers bits) of one instance, any policy: the TLAS is rebuilt
  /// before the next trace (a mask is not a motion, so no refit is involved).
  void set_mask(GeometryId geometry, std::uint32_t instance, std::uint8_t mask);
  /// Replaces a DynamicGeometry procedural geometry's boxes: the same count refits its BLAS before
  /// the next trace, another count rebuilds it. Throws for other policies, triangles or bad boxes.
  void set_aabbs(GeometryId geometry, std::span<const Aabb> boxes);
  /// Replaces a DynamicGeometry triangle geometry's vertex positions (same count, same indices): BLAS refit.
  void set_vertices(GeometryId geometry, std::span<const glm::vec3> vertices);
  /// Replaces a DynamicGeometry triangle geometry's mesh: refit when the indices are the same, else rebuild.
  void set_mesh(GeometryId geometry, TriangleMesh mesh);

  /// Traces one width x height frame and, with `readback`, returns its pixels.
  Frame render(std::uint32_t width, std::uint32_t height, bool readback = true);
  /// Traces a small frame so lazy work (lavapipe compiles shaders at the first trace) is out of
  /// timed frames; returns its wall time in ms.
  double warm_up();

  const BuildTimings& timings() const noexcept { return m_timings; }
  const Pipeline& pipeline() const noexcept { return *m_pipeline; }
  const SbtBuffer& sbt() const noexcept { return *m_sbt; }
  const Tlas& tlas() const noexcept { return m_tlas; }
  /// Bytes of every BLAS (Static ones after compaction).
  VkDeviceSize blas_bytes() const noexcept;

 private:
  /// One scene BLAS: a compacted Static one, or a refittable one with the data it was given.
  struct BlasSlot {
    AccelerationStructure fixed;
    std::unique_ptr<RefittableBlas> dynamic;
    std::vector<std::vector<VkAabbPositionsKHR>> boxes;  // DynamicGeometry procedural: per geometry
    std::vector<TriangleMesh> meshes;                    // DynamicGeometry triangles: per geometry
    bool changed = false;                                // set_* since the last frame
    const AccelerationStructure& get() const { return dynamic ? dynamic->structure() : fixed; }
  };
  const Blas& dynamic_geometry(GeometryId geometry, GeometryKind kind, const char* operation) const;
  void check_movable(GeometryId geometry, const char* operation) const;
  /// The TLAS index of (geometry, instance); InvalidGeometryError naming `operation` when the geometry has no such instance.
  std::uint32_t movable_instance(GeometryId geometry, std::uint32_t instance, const char* operation) const;
  /// InvalidGeometryError naming `operation`, the geometry and the instance for a non-finite or singular matrix.
  void check_transform(GeometryId geometry, std::uint32_t instance, const glm::mat4& m, const char* operation) const;
  /// Rebuilds changed BLASes whose topology changed (each waits) and returns the ones to refit,
  /// which the frame's command buffer records before the TLAS work and the trace.
  std::vector<std::uint32_t> prepare_blases(FrameWork& work);
  void record_refit(VkCommandBuffer cmd, std::uint32_t blas);
  std::vector<AabbGeometry> aabb_geometries(std::uint32_t blas) const;
  std::vector<TriangleGeometry> triangle_geometries(std::uint32_t blas) const;
  struct Uniform {
    std::uint32_t set = 0, binding = 0;
    std::vector<std::byte> value;
    std::unique_ptr<Buffer> buffer;
    bool dirty = false;
  };
  struct Storage {
    std::uint32_t set = 0, binding = 0;
    std::unique_ptr<Buffer> buffer;
  };
  void set_storage_bytes(std::uint32_t set, std::uint32_t binding, std::span<const std::byte> bytes, const char* operation);
  void set_push_bytes(PushConstantBlock slot, const TypeOps* type, std::span<const std::byte> bytes);
  const PushConstantBlock* push_block() const;
  Uniform& uniform(std::uint32_t set, std::uint32_t binding, std::size_t size, const char* operation);
  void build_acceleration_structures();
  void build_descriptor_sets();
  void build_pipeline();
  std::string find_shader(const std::string& name) const;
  void prepare_image(std::uint32_t width, std::uint32_t height);

  using Clock = std::chrono::steady_clock;
  static double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }

  const Context* m_ctx;
  const proceduray::ShaderBindingTable* m_table;
  RendererOptions m_options;
  BuildTimings m_timings;
  std::vector<BlasSlot> m_blases;  // index = scene BLAS; never reallocated (instances point into it)
  std::vector<Instance> m_instances;
  Tlas m_tlas;
  bool m_transforms_dirty = false;
  bool m_tlas_rebuild = false;  // a BLAS was rebuilt: its instances reference a new structure
  std::vector<std::unique_ptr<DescriptorSet>> m_sets;  // index = set number
  std::vector<Uniform> m_uniforms;
  std::vector<Storage> m_storage;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> m_image_bindings;  // (set, binding) of storage images
  std::vector<std::byte> m_push;  // push constant bytes, once set_push gave them
  std::unique_ptr<Pipeline> m_pipeline;
  std::unique_ptr<SbtBuffer> m_sbt;
  std::unique_ptr<StorageImage> m_image;
  DeviceHandle<VkQueryPool> m_queries;
};

// ---------------------------------------------------------------------------------------------

inline Renderer::Renderer(const Context& ctx, const proceduray::ShaderBindingTable& table, RendererOptions options)
    : m_ctx(&ctx), m_table(&table), m_options(std::move(options)) {
  if (m_options.shader_dirs.empty()) m_options.shader_dirs.push_back(std::filesystem::current_path());
  const auto start = Clock::now();
  build_acceleration_structures();
  m_timings.acceleration_ms = ms_since(start);
  build_descriptor_sets();
  build_pipeline();
  m_sbt = std::make_unique<SbtBuffer>(ctx, *m_pipeline, table);
  if (ctx.timestamp_period_ns() > 0) {
    auto info = make<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2;
    VkQueryPool pool = VK_NULL_HANDLE;
    check(vkCreateQueryPool(ctx.device(), &info, nullptr, &pool), "vkCreateQueryPool");
    m_queries = own(ctx.device(), pool, vkDestroyQueryPool);
  }
}

inline void Renderer::build_acceleration_structures() {
  const Scene& scene = m_table->scene();
  m_blases.resize(scene.blases().size());
  bool any_dynamic = false;
  for (std::uint32_t b = 0; b < m_blases.size(); ++b) {
    const Blas& blas = scene.blases()[b];
    BlasSlot& slot = m_blases[b];
    any_dynamic = any_dynamic || blas.update != UpdatePolicy::Static;
    const bool refittable = blas.update == UpdatePolicy::DynamicGeometry;
    for (GeometryId id : blas.geometries) {
      const GeometryDesc& desc = scene.geometry(id).desc;
      if (blas.kind == GeometryKind::procedural) {
        auto& list = slot.boxes.emplace_back();
        for (const Aabb& a : desc.aabbs) list.push_back({a.min.x, a.min.y, a.min.z, a.max.x, a.max.y, a.max.z});
      } else if (refittable) {
        slot.meshes.push_back(desc.mesh);  // the renderer's own copy: set_vertices and set_mesh change it
      }
    }
    if (blas.kind == GeometryKind::procedural) {
      const auto geometries = aabb_geometries(b);
      if (refittable) slot.dynamic = std::make_unique<RefittableBlas>(*m_ctx, std::span<const AabbGeometry>(geometries));
      else slot.fixed = build_blas(*m_ctx, std::span<const AabbGeometry>(geometries), m_options.blas);
      if (!refittable) slot.boxes.clear();  // the scene keeps Static boxes
    } else if (refittable) {
      const auto geometries = triangle_geometries(b);
      slot.dynamic = std::make_unique<RefittableBlas>(*m_ctx, std::span<const TriangleGeometry>(geometries));
    } else {
      std::vector<TriangleGeometry> geometries;  // straight from the scene: a Static mesh is not copied
      for (GeometryId id : blas.geometries) {
        const GeometryDesc& desc = scene.geometry(id).desc;
        geometries.push_back({desc.mesh.vertices, desc.mesh.indices, desc.opaque});
      }
      slot.fixed = build_blas(*m_ctx, std::span<const TriangleGeometry>(geometries), m_options.blas);
    }
  }
  const auto instances = m_table->instances();
  for (std::uint32_t k = 0; k < instances.size(); ++k) {
    const InstanceTransform& t = m_table->transform(instances[k]);
    glm::mat4 m(1.0f);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) m[c][r] = t[r][c];  // InstanceTransform holds the rows of the 3x4 matrix
    m_instances.push_back({.blas = &m_blases[instances[k].blas].get(), .transform = m, .custom_index = k,
                           .sbt_offset = instances[k].sbt_offset, .mask = instances[k].mask});
  }
  // Only a scene that changes pays for a refittable TLAS.
  m_tlas = Tlas(*m_ctx, m_instances, {.allow_update = any_dynamic});
}

inline std::vector<AabbGeometry> Renderer::aabb_geometries(std::uint32_t b) const {
  const Scene& scene = m_table->scene();
  const Blas& blas = scene.blases()[b];
  std::vector<AabbGeometry> out;
  for (std::size_t g = 0; g < blas.geometries.size(); ++g) {
    out.push_back({m_blases[b].boxes[g], scene.geometry(blas.geometries[g]).desc.opaque});
  }
  return out;
}

inline std::vector<TriangleGeometry> Renderer::triangle_geometries(std::uint32_t b) const {
  const Scene& scene = m_table->scene();
  const Blas& blas = scene.blases()[b];
  std::vector<TriangleGeometry> out;
  for (std::size_t g = 0; g < blas.geometries.size(); ++g) {
    const TriangleMesh& mesh = m_blases[b].meshes[g];
    out.push_back({mesh.vertices, mesh.indices, scene.geometry(blas.geometries[g]).desc.opaque});
  }
  return out;
}

inline void Renderer::build_descriptor_sets() {
  const PipelinePlan& plan = m_table->plan();
  if (!plan.global_signature.valid()) return;
  const auto& desc = m_table->scene().global_signature(plan.global_signature).desc;
  std::map<std::uint32_t, std::vector<Binding>> by_set;
  std::uint32_t last_set = 0;
  for (const proceduray::Binding& b : desc.bindings) {
    if (b.count != 1) {
      throw UsageError("Renderer: set " + std::to_string(b.set) + " binding " + std::to_string(b.binding) +
                       " is an array of " + std::to_string(b.count) +
                       "; descriptor arrays are not supported yet: use one binding per resource");
    }
    static constexpr VkDescriptorType types[] = {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR,
                                                 VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                                 VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
    by_set[b.set].push_back({b.binding, types[static_cast<std::uint32_t>(b.kind)]});
    last_set = std::max(last_set, b.set);
  }
  // Set numbers in the pipeline layout are positions: a gap gets an empty set.
  for (std::uint32_t s = 0; s <= last_set; ++s) m_sets.push_back(std::make_unique<DescriptorSet>(*m_ctx, by_set[s]));
  for (const proceduray::Binding& b : desc.bindings) {
    switch (b.kind) {
      case BindingKind::acceleration_structure: m_sets[b.set]->write(b.binding, m_tlas.structure()); break;
      case BindingKind::storage_image: m_image_bindings.emplace_back(b.set, b.binding); break;
      case BindingKind::uniform_buffer: m_uniforms.push_back({b.set, b.binding, {}, nullptr, false}); break;
      case BindingKind::storage_buffer: m_storage.push_back({b.set, b.binding, nullptr}); break;
    }
  }
}

inline std::string Renderer::find_shader(const std::string& name) const {
  std::string tried;
  for (const auto& dir : m_options.shader_dirs) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(dir / name, ec)) return (dir / name).string();
    tried += " '" + dir.string() + "'";
  }
  throw UsageError("Renderer: shader '" + name + "' is not in any shader folder (searched" + tried +
                   "); add its folder to RendererOptions::shader_dirs or fix the name in the scene");
}

inline void Renderer::build_pipeline() {
  const PipelinePlan& plan = m_table->plan();
  PipelineDesc desc;
  if (plan.global_signature.valid()) {  // checked before compiling: a size error is the clearer one
    const std::uint32_t bytes = m_table->scene().global_signature(plan.global_signature).desc.push_bytes();
    const std::uint32_t limit = m_ctx->properties().limits.maxPushConstantsSize;
    if (bytes > limit) {
      throw DeviceLimitError("Renderer: the global signature declares " + std::to_string(bytes) +
                             " bytes of push constants, " + m_ctx->name() + " allows " + std::to_string(limit) +
                             " (maxPushConstantsSize; every device allows 128); move the rest to a uniform");
    }
  }
  auto start = Clock::now();
  for (const PlannedStage& stage : plan.stages) {
    const std::string path = find_shader(stage.shader);
    std::string preamble = m_options.declarations ? m_options.declarations(stage.stage, stage.shader)
                                                  : glsl_for(*m_table, stage.stage, stage.shader) + m_options.extra_declarations;
    std::vector<std::uint32_t> spirv = compile_glsl({.stage = stage.stage, .name = path, .code = read_text_file(path),
                                                     .preamble = std::move(preamble)});
    check_recursion_depth("Renderer", stage.stage, stage.shader, spirv, plan.max_recursion_depth,
                          plan.recursion_depth_declared, "call ShaderTable::set_max_recursion_depth(n)");  // throws
    desc.add_shader(stage.stage, std::move(spirv));
  }
  m_timings.compile_ms = ms_since(start);
  for (const PlannedGroup& g : plan.groups) {
    static constexpr VkRayTracingShaderGroupTypeKHR types[] = {VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR,
                                                               VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR,
                                                               VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR};
    desc.groups.push_back({types[static_cast<std::uint32_t>(g.type)], g.general, g.closest_hit, g.any_hit, g.intersection});
  }
  for (const auto& set : m_sets) desc.set_layouts.push_back(set->layout());
  if (plan.global_signature.valid()) {
    desc.push_constant_size = m_table->scene().global_signature(plan.global_signature).desc.push_bytes();
  }
  desc.max_recursion_depth = plan.max_recursion_depth;
  PipelineCache cache(*m_ctx, m_options.pipeline_cache);
  desc.cache = cache.get();
  start = Clock::now();
  m_pipeline = std::make_unique<Pipeline>(*m_ctx, desc);
  m_timings.pipeline_ms = ms_since(start);
  m_timings.pipeline_cached = cache.loaded();
  cache.save();
}

inline Renderer::Uniform& Renderer::uniform(std::uint32_t set, std::uint32_t binding, std::size_t size,
                                            const char* operation) {
  for (Uniform& u : m_uniforms) {
    if (u.set != set || u.binding != binding) continue;
    if (!u.buffer) {
      u.value.resize(size);
      u.buffer = std::make_unique<Buffer>(*m_ctx, size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      m_sets[set]->write(binding, *u.buffer);
    }
    return u;
  }
  throw UsageError(std::string(operation) + ": set " + std::to_string(set) + " binding " +
                   std::to_string(binding) + " is not a uniform buffer of the global signature; "
                   "declare it there (a UniformSlot converts to its Binding)");
}

inline void Renderer::set_storage_bytes(std::uint32_t set, std::uint32_t binding, std::span<const std::byte> bytes,
                                         const char* operation) {
  for (Storage& s : m_storage) {
    if (s.set != set || s.binding != binding) continue;
    if (bytes.empty()) {
      throw UsageError(std::string(operation) + ": no elements given for set " + std::to_string(set) +
                       " binding " + std::to_string(binding) + "; a storage buffer needs at least one");
    }
    if (!s.buffer || s.buffer->size() < bytes.size()) {
      s.buffer = std::make_unique<Buffer>(*m_ctx, bytes.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      m_sets[set]->write(binding, *s.buffer);
    }
    s.buffer->write(bytes);
    return;
  }
  throw UsageError(std::string(operation) + ": set " + std::to_string(set) + " binding " +
                   std::to_string(binding) + " is not a storage buffer of the global signature; "
                   "declare it there (a StorageSlot converts to its Binding)");
}

inline const PushConstantBlock* Renderer::push_block() const {
  const PipelinePlan& plan = m_table->plan();
  if (!plan.global_signature.valid()) return nullptr;
  return &m_table->scene().global_signature(plan.global_signature).desc.push_constants;
}

inline void Renderer::set_push_bytes(PushConstantBlock slot, const TypeOps* type, std::span<const std::byte> bytes) {
  const PushConstantBlock* block = push_block();
  if (block == nullptr || block->type == nullptr) {
    throw UsageError(std::string("Renderer::set_push: the global signature declares no typed push constants (") +
                     std::to_string(m_pipeline->push_constant_size()) + " untyped bytes); declare them with "
                     "GlobalSignatureDesc::push_constants = a PushConstantSlot<" + std::string(type->glsl_name) + ">");
  }
  if (block->type != type || block->name != slot.name) {
    throw UsageError("Renderer::set_push: the slot holds " + std::string(type->glsl_name) + " \"" + slot.name +
                     "\" but the global signature declares " + std::string(block->type->glsl_name) + " \"" +
                     block->name + "\"; pass the slot the signature was declared with");
  }
  m_push.assign(bytes.begin(), bytes.end());
}

inline void Renderer::check_movable(GeometryId geometry, const char* operation) const {
  const Scene& scene = m_table->scene();
  if (scene.blas_of(geometry).update == UpdatePolicy::Static) {
    throw UsageError(std::string(operation) + ": geometry \"" + scene.geometries().name(geometry.index()) +
                     "\" is Static, so its instances were built not to move; declare it with "
                     "update = UpdatePolicy::DynamicTransform");
  }
}

inline std::uint32_t Renderer::movable_instance(GeometryId geometry, std::uint32_t instance, const char* operation) const {
  const Scene& scene = m_table->scene();
  const std::size_t count = scene.blas_of(geometry).instances.size();
  if (instance >= count) {
    throw InvalidGeometryError(std::string(operation) + ": geometry \"" + scene.geometries().name(geometry.index()) +
                               "\" has " + std::to_string(count) + " instances, no instance " + std::to_string(instance) +
                               "; pass an instance index below " + std::to_string(count) +
                               " (the order of GeometryDesc::instances)");
  }
  check_movable(geometry, operation);
  return m_table->tlas_index(geometry, instance, operation);
}

inline void Renderer::check_transform(GeometryId geometry, std::uint32_t instance, const glm::mat4& m,
                                      const char* operation) const {
  detail::check_matrix(m, [&] {
    return std::string(operation) + ": geometry \"" + m_table->scene().geometries().name(geometry.index()) +
           "\" instance " + std::to_string(instance) + " transform";
  });
}

inline void Renderer::set_transforms(GeometryId geometry, std::span<const glm::mat4> object_to_world) {
  constexpr const char* op = "Renderer::set_transforms";
  const Scene& scene = m_table->scene();
  check_movable(geometry, op);
  const std::size_t count = scene.blas_of(geometry).instances.size();
  if (object_to_world.size() != count) {
    throw InvalidGeometryError(std::string(op) + ": geometry \"" + scene.geometries().name(geometry.index()) +
                               "\" has " + std::to_string(count) + " instances, " +
                               std::to_string(object_to_world.size()) + " transforms given; give one per instance");
  }
  // A BLAS's instances are consecutive in the TLAS. All are checked before any moves, so a bad
  // matrix leaves every instance where it was.
  const std::uint32_t first = m_table->tlas_index(geometry, 0, op);
  for (std::uint32_t i = 0; i < count; ++i) check_transform(geometry, i, object_to_world[i], op);  // throws
  for (std::size_t i = 0; i < count; ++i) m_instances[first + i].transform = object_to_world[i];
  m_transforms_dirty = true;
}

inline void Renderer::set_mask(GeometryId geometry, std::uint32_t instance, std::uint8_t mask) {
  const std::uint32_t k = m_table->tlas_index(geometry, instance, "Renderer::set_mask");
  if (m_instances[k].mask == mask) return;
  m_instances[k].mask = mask;
  m_tlas_rebuild = true;
}

inline void Renderer::set_transform(GeometryId geometry, std::uint32_t instance, const glm::mat4& object_to_world) {
  constexpr const char* op = "Renderer::set_transform";
  const std::uint32_t k = movable_instance(geometry, instance, op);
  check_transform(geometry, instance, object_to_world, op);  // throws
  m_instances[k].transform = object_to_world;
  m_transforms_dirty = true;
}

inline const Blas& Renderer::dynamic_geometry(GeometryId geometry, GeometryKind kind, const char* operation) const {
  const Scene& scene = m_table->scene();
  const Geometry& g = scene.geometry(geometry);
  const Blas& blas = scene.blases()[g.blas];
  const std::string name = scene.geometries().name(geometry.index());
  if (blas.update != UpdatePolicy::DynamicGeometry) {
    throw UsageError(std::string(operation) + ": geometry \"" + name + "\" is " + to_string(blas.update) +
                     ", so its BLAS was built not to change; declare it with "
                     "update = UpdatePolicy::DynamicGeometry");
  }
  if (blas.kind != kind) {
    throw UsageError(std::string(operation) + ": geometry \"" + name + "\" is " + to_string(blas.kind) +
                     (kind == GeometryKind::procedural ? "; change its vertices with set_vertices or set_mesh"
                                                       : "; change its boxes with set_aabbs"));
  }
  return blas;
}

inline void Renderer::set_aabbs(GeometryId geometry, std::span<const Aabb> boxes) {
  constexpr const char* op = "Renderer::set_aabbs";
  dynamic_geometry(geometry, GeometryKind::procedural, op);
  const Geometry& g = m_table->scene().geometry(geometry);
  const std::string where = std::string(op) + ": geometry \"" + m_table->scene().geometries().name(geometry.index()) + "\"";
  if (boxes.empty()) throw InvalidGeometryError(where + " given no boxes; give it at least one AABB");
  std::vector<VkAabbPositionsKHR> list;
  list.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (!proceduray::detail::valid_box(boxes[i])) validate(boxes[i], where + " AABB " + std::to_string(i));  // throws
    const Aabb& a = boxes[i];
    list.push_back({a.min.x, a.min.y, a.min.z, a.max.x, a.max.y, a.max.z});
  }
  BlasSlot& slot = m_blases[g.blas];
  slot.boxes[g.geometry_index] = std::move(list);
  slot.changed = true;
}

inline void Renderer::set_vertices(GeometryId geometry, std::span<const glm::vec3> vertices) {
  constexpr const char* op = "Renderer::set_vertices";
  dynamic_geometry(geometry, GeometryKind::triangles, op);
  const Geometry& g = m_table->scene().geometry(geometry);
  TriangleMesh mesh = m_blases[g.blas].meshes[g.geometry_index];
  if (vertices.size() != mesh.vertices.size()) {
    throw InvalidGeometryError(std::string(op) + ": geometry \"" + m_table->scene().geometries().name(geometry.index()) +
                               "\" has " + std::to_string(mesh.vertices.size()) + " vertices, " +
                               std::to_string(vertices.size()) + " given; new positions keep the count: "
                               "call set_mesh to change the topology");
  }
  mesh.vertices.assign(vertices.begin(), vertices.end());
  set_mesh(geometry, std::move(mesh));
}

inline void Renderer::set_mesh(GeometryId geometry, TriangleMesh mesh) {
  constexpr const char* op = "Renderer::set_mesh";
  dynamic_geometry(geometry, GeometryKind::triangles, op);
  const Scene& scene = m_table->scene();
  GeometryDesc check = GeometryDesc::triangles(mesh, {});
  validate(check, scene.geometries().name(geometry.index()), op);  // throws InvalidGeometryError naming the geometry
  const Geometry& g = scene.geometry(geometry);
  BlasSlot& slot = m_blases[g.blas];
  slot.meshes[g.geometry_index] = std::move(mesh);
  slot.changed = true;
}

inline void Renderer::record_refit(VkCommandBuffer cmd, std::uint32_t b) {
  RefittableBlas& blas = *m_blases[b].dynamic;
  if (m_table->scene().blases()[b].kind == GeometryKind::procedural) {
    blas.record_refit(*m_ctx, cmd, std::span<const AabbGeometry>(aabb_geometries(b)));
  } else {
    blas.record_refit(*m_ctx, cmd, std::span<const TriangleGeometry>(triangle_geometries(b)));
  }
}

inline std::vector<std::uint32_t> Renderer::prepare_blases(FrameWork& work) {
  const Scene& scene = m_table->scene();
  std::vector<std::uint32_t> refits;
  for (std::uint32_t b = 0; b < m_blases.size(); ++b) {
    BlasSlot& slot = m_blases[b];
    if (!slot.changed) continue;
    slot.changed = false;
    const bool procedural = scene.blases()[b].kind == GeometryKind::procedural;
    const auto boxes = procedural ? aabb_geometries(b) : std::vector<AabbGeometry>{};
    const auto meshes = procedural ? std::vector<TriangleGeometry>{} : triangle_geometries(b);
    const bool refit = procedural ? slot.dynamic->same_topology(std::span<const AabbGeometry>(boxes))
                                  : slot.dynamic->same_topology(std::span<const TriangleGeometry>(meshes));
    if (refit) {
      refits.push_back(b);
      ++work.blas_refits;
      m_transforms_dirty = true;  // the TLAS holds the old bounds: refit it
    } else {
      // A new structure (the old one is freed whole, handle before memory); its instances point at it.
      slot.dynamic = procedural ? std::make_unique<RefittableBlas>(*m_ctx, std::span<const AabbGeometry>(boxes))
                                : std::make_unique<RefittableBlas>(*m_ctx, std::span<const TriangleGeometry>(meshes));
      const auto instances = m_table->instances();
      for (std::size_t k = 0; k < instances.size(); ++k) {
        if (instances[k].blas == b) m_instances[k].blas = &slot.dynamic->structure();
      }
      ++work.blas_builds;
      m_tlas_rebuild = true;
    }
  }
  return refits;
}

inline void Renderer::prepare_image(std::uint32_t width, std::uint32_t height) {
  if (m_image && m_image->width() == width && m_image->height() == height) return;
  m_image = std::make_unique<StorageImage>(*m_ctx, width, height);
  for (auto [set, binding] : m_image_bindings) m_sets[set]->write(binding, m_image->view());
}

inline Frame Renderer::render(std::uint32_t width, std::uint32_t height, bool readback) {
  check_trace_size(*m_ctx, width, height);
  for (const Uniform& u : m_uniforms) {
    if (!u.buffer) {
      throw UsageError("Renderer::render: the uniform at set " + std::to_string(u.set) + " binding " +
                       std::to_string(u.binding) + " was never given a value; call set(slot, value) first");
    }
  }
  for (const Storage& s : m_storage) {
    if (!s.buffer) {
      throw UsageError("Renderer::render: the storage buffer at set " + std::to_string(s.set) + " binding " +
                       std::to_string(s.binding) + " was never given data; call set_storage(slot, values) first");
    }
  }
  if (m_pipeline->push_constant_size() != m_push.size()) {
    const PushConstantBlock* block = push_block();
    throw UsageError(
        "Renderer::render: the global signature declares " + std::to_string(m_pipeline->push_constant_size()) +
        " bytes of push constants but " +
        (block != nullptr && block->type != nullptr
       ? std::string("they were never given a value; call set_push(slot, value) first")
       : std::string("they are untyped, so the renderer cannot fill them; declare them with a PushConstantSlot<T>")));
  }
  prepare_image(width, height);
  Frame frame{width, height, {}, 0, 0, false, {}};
  const std::vector<std::uint32_t> refits = prepare_blases(frame.work);
  if (m_tlas_rebuild) ++frame.work.tlas_builds;
  else if (m_transforms_dirty) ++frame.work.tlas_updates;
  frame.tlas_refit = frame.work.tlas_builds + frame.work.tlas_updates > 0;
  const auto host_start = Clock::now();
  for (Uniform& u : m_uniforms) {
    if (u.dirty) u.buffer->write(std::span<const std::byte>(u.value));
    u.dirty = false;
  }
  double recorded_ms = 0;
  const auto wall_start = Clock::now();
  m_ctx->submit([&](VkCommandBuffer cmd) {
    for (std::uint32_t b : refits) record_refit(cmd, b);  // each ends with a barrier for the TLAS build
    if (m_tlas_rebuild) m_tlas.record_build(*m_ctx, cmd, m_instances);
    else if (m_transforms_dirty) m_tlas.record_update(*m_ctx, cmd, m_instances);
    m_transforms_dirty = false;
    m_tlas_rebuild = false;
    std::vector<VkDescriptorSet> sets;
    for (const auto& s : m_sets) sets.push_back(s->get());
    if (m_queries) vkCmdResetQueryPool(cmd, m_queries.get(), 0, 2);
    const VkQueryPool queries = m_queries.get();
    auto stamp = [queries](VkPipelineStageFlagBits stage, std::uint32_t query) {
      return [=](VkCommandBuffer c) {
        if (queries != VK_NULL_HANDLE) vkCmdWriteTimestamp(c, stage, queries, query);
      };
    };
    record_trace(*m_ctx, cmd, *m_pipeline, sets, *m_sbt, width, height, m_push,
                 std::function<void(VkCommandBuffer)>(stamp(VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0)),
                 std::function<void(VkCommandBuffer)>(stamp(VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 1)));
    recorded_ms = ms_since(host_start);
  });
  frame.host_ms = recorded_ms;
  if (m_queries) {
    std::uint64_t stamps[2] = {};
    check(vkGetQueryPoolResults(m_ctx->device(), m_queries.get(), 0, 2, sizeof stamps, stamps, sizeof stamps[0],
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults", "trace timestamps");
    frame.trace_ms = static_cast<double>(stamps[1] - stamps[0]) * m_ctx->timestamp_period_ns() * 1e-6;
  } else {
    frame.trace_ms = ms_since(wall_start);
  }
  if (readback) frame.rgba = m_image->read();
  return frame;
}

inline double Renderer::warm_up() {
  const auto start = Clock::now();
  render(8, 8, false);
  return ms_since(start);
}

inline VkDeviceSize Renderer::blas_bytes() const noexcept {
  VkDeviceSize total = 0;
  for (const auto& b : m_blases) total += b.get().size();
  return total;
}

}  // namespace proceduray::vk
