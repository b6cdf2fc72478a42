// The renderer: everything a built shader table implies, made on the device, and frames traced.
//
//   proceduray::ShaderBindingTable sbt = table.build(ctx.limits());
//   proceduray::vk::Renderer renderer(ctx, sbt, {.shader_dirs = {"shaders"},
//                                                .pipeline_cache = "proceduray.cache"});
//   renderer.set(constants_slot, constants);          // typed uniform, uploaded before the next trace
//   renderer.set_storage(tints_slot, tints);          // typed storage buffer (an array)
//   renderer.set_transform(pacman, 1, moved);         // TLAS refit before the next trace, no BLAS work
//   proceduray::vk::Frame frame = renderer.render(1024, 768);
//   frame.rgba; frame.trace_ms;                       // pixels, GPU time of the trace
//
// From the table it makes: one BLAS per scene BLAS (triangles or AABBs, compacted), a
// refittable TLAS whose instances carry the SBT offsets the scene assigned, descriptor sets
// from the global signature (the acceleration-structure binding gets the TLAS, the storage
// image binding the frame, uniform bindings the values given with set()), the pipeline from
// the plan (shaders read from shader_dirs, compiled with the declarations glsl_for derives, the
// stack size from the groups' own sizes, a disk cache when asked), and the SBT bytes.
// The table and its scene must outlive the renderer.
#pragma once

#include <proceduray/scene/glsl_for.hpp>
#include <proceduray/scene/shader_binding_table.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/vk/acceleration.hpp>
#include <proceduray/vk/descriptors.hpp>
#include <proceduray/vk/pipeline.hpp>
#include <proceduray/vk/pipeline_cache.hpp>
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

/// One traced frame.
struct Frame {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> rgba;  ///< width * height RGBA8 pixels, rows top to bottom; empty without readback
  double trace_ms = 0;  ///< GPU time between timestamps around vkCmdTraceRaysKHR (wall time if the queue has none)
  double host_ms = 0;   ///< host work before submit: uniform uploads, TLAS instance writes, command recording
  bool tlas_refit = false;  ///< the frame refit the TLAS (a transform changed)
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
  /// Moves instance `instance` of `geometry`; the TLAS is refit before the next trace (no BLAS work).
  void set_transform(GeometryId geometry, std::uint32_t instance, const glm::mat4& object_to_world);

  /// Traces one width x height frame and, with `readback`, returns its pixels.
  Frame render(std::uint32_t width, std::uint32_t height, bool readback = true);
  /// Traces a small frame so lazy work (lavapipe compiles shaders at the first trace) is out of
  /// timed frames; returns its wall time in ms.
  double warm_up();

  const BuildTimings& timings() const noexcept { return m_timings; }
  const Pipeline& pipeline() const noexcept { return *m_pipeline; }
  const SbtBuffer& sbt() const noexcept { return *m_sbt; }
  const Tlas& tlas() const noexcept { return m_tlas; }
  /// Bytes of every BLAS after compaction.
  VkDeviceSize blas_bytes() const noexcept;

 private:
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
  std::vector<AccelerationStructure> m_blases;
  std::vector<Instance> m_instances;
  Tlas m_tlas;
  bool m_transforms_dirty = false;
  std::vector<std::unique_ptr<DescriptorSet>> m_sets;  // index = set number
  std::vector<Uniform> m_uniforms;
  std::vector<Storage> m_storage;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> m_image_bindings;  // (set, binding) of storage images
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
  for (const Blas& blas : scene.blases()) {
    if (blas.kind == GeometryKind::procedural) {
      std::vector<std::vector<VkAabbPositionsKHR>> boxes;
      std::vector<AabbGeometry> geometries;
      for (GeometryId id : blas.geometries) {
        const GeometryDesc& desc = scene.geometry(id).desc;
        auto& list = boxes.emplace_back();
        for (const Aabb& b : desc.aabbs) list.push_back({b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z});
      }
      for (std::size_t g = 0; g < boxes.size(); ++g) {
        geometries.push_back({boxes[g], scene.geometry(blas.geometries[g]).desc.opaque});
      }
      m_blases.push_back(build_blas(*m_ctx, std::span<const AabbGeometry>(geometries), m_options.blas));
    } else {
      std::vector<TriangleGeometry> geometries;
      for (GeometryId id : blas.geometries) {
        const GeometryDesc& desc = scene.geometry(id).desc;
        geometries.push_back({desc.mesh.vertices, desc.mesh.indices, desc.opaque});
      }
      m_blases.push_back(build_blas(*m_ctx, std::span<const TriangleGeometry>(geometries), m_options.blas));
    }
  }
  const auto instances = m_table->instances();
  for (std::uint32_t k = 0; k < instances.size(); ++k) {
    const InstanceTransform& t = m_table->transform(instances[k]);
    glm::mat4 m(1.0f);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) m[c][r] = t[r][c];  // InstanceTransform holds the rows of the 3x4 matrix
    m_instances.push_back({.blas = &m_blases[instances[k].blas], .transform = m, .custom_index = k,
                           .sbt_offset = instances[k].sbt_offset});
  }
  m_tlas = Tlas(*m_ctx, m_instances, {.allow_update = true});
}

inline void Renderer::build_descriptor_sets() {
  const PipelinePlan& plan = m_table->plan();
  if (!plan.global_signature.valid()) return;
  const auto& desc = m_table->scene().global_signature(plan.global_signature).desc;
  std::map<std::uint32_t, std::vector<Binding>> by_set;
  std::uint32_t last_set = 0;
  for (const proceduray::Binding& b : desc.bindings) {
    if (b.count != 1) {
      throw std::invalid_argument("Renderer: set " + std::to_string(b.set) + " binding " + std::to_string(b.binding) +
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
  throw std::runtime_error("Renderer: shader '" + name + "' is not in any shader folder (searched" + tried +
                           "); add its folder to RendererOptions::shader_dirs or fix the name in the scene");
}

inline void Renderer::build_pipeline() {
  const PipelinePlan& plan = m_table->plan();
  PipelineDesc desc;
  auto start = Clock::now();
  for (const PlannedStage& stage : plan.stages) {
    const std::string path = find_shader(stage.shader);
    std::string preamble = m_options.declarations ? m_options.declarations(stage.stage, stage.shader)
                                                  : glsl_for(*m_table, stage.stage, stage.shader) + m_options.extra_declarations;
    desc.add_shader(stage.stage, compile_glsl({.stage = stage.stage, .name = path, .code = read_text_file(path),
                                               .preamble = std::move(preamble)}));
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
    desc.push_constant_size = m_table->scene().global_signature(plan.global_signature).desc.push_constant_size;
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
  throw std::invalid_argument(std::string(operation) + ": set " + std::to_string(set) + " binding " +
                              std::to_string(binding) + " is not a uniform buffer of the global signature; "
                              "declare it there (a UniformSlot converts to its Binding)");
}

inline void Renderer::set_storage_bytes(std::uint32_t set, std::uint32_t binding, std::span<const std::byte> bytes,
                                         const char* operation) {
  for (Storage& s : m_storage) {
    if (s.set != set || s.binding != binding) continue;
    if (bytes.empty()) {
      throw std::invalid_argument(std::string(operation) + ": no elements given for set " + std::to_string(set) +
                                  " binding " + std::to_string(binding) + "; a storage buffer needs at least one");
    }
    if (!s.buffer || s.buffer->size() < bytes.size()) {
      s.buffer = std::make_unique<Buffer>(*m_ctx, bytes.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      m_sets[set]->write(binding, *s.buffer);
    }
    s.buffer->write(bytes);
    return;
  }
  throw std::invalid_argument(std::string(operation) + ": set " + std::to_string(set) + " binding " +
                              std::to_string(binding) + " is not a storage buffer of the global signature; "
                              "declare it there (a StorageSlot converts to its Binding)");
}

inline void Renderer::set_transform(GeometryId geometry, std::uint32_t instance, const glm::mat4& object_to_world) {
  const std::uint32_t k = m_table->tlas_index(geometry, instance, "Renderer::set_transform");
  Instance moved = m_instances[k];
  moved.transform = object_to_world;
  VkAccelerationStructureInstanceKHR packed{};
  detail::pack_instances({&moved, 1}, {&packed, 1});  // throws for a non-finite or singular transform
  m_instances[k] = moved;
  m_transforms_dirty = true;
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
      throw std::logic_error("Renderer::render: the uniform at set " + std::to_string(u.set) + " binding " +
                             std::to_string(u.binding) + " was never given a value; call set(slot, value) first");
    }
  }
  for (const Storage& s : m_storage) {
    if (!s.buffer) {
      throw std::logic_error("Renderer::render: the storage buffer at set " + std::to_string(s.set) + " binding " +
                             std::to_string(s.binding) + " was never given data; call set_storage(slot, values) first");
    }
  }
  prepare_image(width, height);
  Frame frame{width, height, {}, 0, 0, m_transforms_dirty};
  const auto host_start = Clock::now();
  for (Uniform& u : m_uniforms) {
    if (u.dirty) u.buffer->write(std::span<const std::byte>(u.value));
    u.dirty = false;
  }
  double recorded_ms = 0;
  const auto wall_start = Clock::now();
  m_ctx->submit([&](VkCommandBuffer cmd) {
    if (m_transforms_dirty) m_tlas.record_update(*m_ctx, cmd, m_instances);
    m_transforms_dirty = false;
    std::vector<VkDescriptorSet> sets;
    for (const auto& s : m_sets) sets.push_back(s->get());
    if (m_queries) vkCmdResetQueryPool(cmd, m_queries.get(), 0, 2);
    const VkQueryPool queries = m_queries.get();
    auto stamp = [queries](VkPipelineStageFlagBits stage, std::uint32_t query) {
      return [=](VkCommandBuffer c) {
        if (queries != VK_NULL_HANDLE) vkCmdWriteTimestamp(c, stage, queries, query);
      };
    };
    record_trace(*m_ctx, cmd, *m_pipeline, sets, *m_sbt, width, height, {},
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
  for (const auto& b : m_blases) total += b.size();
  return total;
}

}  // namespace proceduray::vk
