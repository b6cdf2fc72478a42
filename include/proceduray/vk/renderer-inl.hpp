// The bodies of proceduray/vk/renderer.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/renderer.hpp"

#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#if PROCEDURAY_BODIES

namespace proceduray::vk {

PROCEDURAY_DECL Renderer::Renderer(const Context& ctx, proceduray::Plan plan, RendererOptions given)
    : m_ctx(ctx), m_options(std::move(given)), m_plan(std::move(plan)) {
  // Everything below is made from this renderer's own copy of the context, which keeps the device
  // alive until they are gone, whatever happens to the caller's `ctx`.
  const RendererOptions& options = m_options;
  m_ring = std::make_unique<FrameRing>(m_ctx, options.frames_in_flight, "Renderer: RendererOptions::frames_in_flight");
  m_slot_frames.resize(m_ring->size());
  if (const auto raygen = m_plan.records(SbtRegionKind::raygen); raygen.size() > 1) {
    throw UsageError("Renderer: the scene has " + std::to_string(raygen.size()) + " raygen entries (first \"" +
                     m_plan.pipeline().groups[raygen[0].group].name + "\", second \"" +
                     m_plan.pipeline().groups[raygen[1].group].name + "\"); a Renderer traces one raygen: keep "
                     "one per scene, or make one scene per raygen");
  }
  // Every device limit is checked once, before any device object is made: the plan's (layout),
  // then the depth the stages' tracing settles, when derived.
  m_layout = m_plan.layout(m_ctx.limits());
  m_stages = compile_scene_stages(m_plan, options);
  FieldKnobs::check_picks(m_plan, m_ctx.name(), options.shader_dirs.empty() ?
      std::vector<std::filesystem::path>{std::filesystem::current_path()} : options.shader_dirs, "Renderer");
  m_plan.settle_recursion(m_stages.traces, m_ctx.limits(), "Renderer");
  const auto start = Clock::now();
  m_structures = std::make_unique<SceneAcceleration>(m_ctx, m_plan, options.blas);
  m_timings.acceleration_ms = ms_since(start);
  m_bindings = std::make_unique<Bindings>(m_ctx, m_plan.global_signature(), m_structures->tlas().structure(),
                                          static_cast<std::uint32_t>(m_plan.instances().size()));
  m_fields = std::make_unique<FieldKnobs>(m_plan, *m_bindings);
  m_meshes = std::make_unique<MeshBuffers>(m_ctx, m_plan);
  PipelineTimings pipeline;
  build_pipeline(&pipeline);
  m_timings.compile_ms = pipeline.compile_ms;
  m_timings.pipeline_ms = pipeline.pipeline_ms;
  m_timings.pipeline_cached = pipeline.pipeline_cached;
  m_timings.spirv_cached = pipeline.spirv_cached;
  m_timings.spirv_compiled = pipeline.spirv_compiled;
  // Only a specialized pipeline is built again: the general one keeps no SPIR-V.
  if (!m_options.specialize_fields || m_plan.fields().empty()) m_stages = {};
  m_outputs = std::make_unique<OutputImages>(m_ctx, m_plan.outputs(), m_plan.depth_binding());
}

PROCEDURAY_DECL void Renderer::build_pipeline(PipelineTimings* timings) {
  const bool specialize = m_options.specialize_fields && !m_plan.fields().empty();
  const std::vector<MarchKnobs> knobs = specialize ? m_fields->knobs() : std::vector<MarchKnobs>{};
  // A copy of the SPIR-V while a knob change may need it again; else the modules themselves.
  SceneStages stages = specialize ? m_stages : std::move(m_stages);
  m_sbt.reset();  // it points at the old pipeline's group handles
  m_pipeline = make_scene_pipeline(m_ctx, m_plan, std::move(stages), m_bindings->layouts(), m_bindings->push_size(),
                                   m_options, timings, knobs);
  m_sbt = std::make_unique<SbtBuffer>(m_ctx, *m_pipeline, m_plan, m_layout, m_meshes->addresses());
  m_pipeline_knobs = m_fields->version();
}

PROCEDURAY_DECL void Renderer::prepare(std::uint32_t width, std::uint32_t height, std::string_view op) {
  check_trace_size(m_ctx, width, height);
  if (m_fields->dirty()) m_ring->wait_all();  // the settings buffer is written in place
  if (m_options.specialize_fields && m_fields->version() != m_pipeline_knobs) {
    const auto start = Clock::now();  // after the wait above: no frame in flight uses the old ones
    build_pipeline(nullptr);
    ++m_timings.rebuilds;
    m_timings.rebuild_ms += ms_since(start);
  }
  m_fields->upload(*m_bindings, op);
  m_bindings->check_ready(op);
  if (m_image && m_image->width() == width && m_image->height() == height) return;
  // New images, bound in the descriptor sets: no frame in flight may still use the old ones.
  m_ring->wait_all();
  m_outputs->resize(width, height, *m_bindings);
  m_image = std::make_unique<StorageImage>(m_ctx, width, height, VK_FORMAT_R8G8B8A8_UNORM, StorageImage::recorded);
  m_bindings->bind_image(m_image->view());
}

PROCEDURAY_DECL FrameWork Renderer::record_frame(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height, Stamp before,
                                                 Stamp after) {
  // The frame before may still run: its trace and copies before this frame's builds, clears and writes.
  auto barrier = make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                          VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR | VK_PIPELINE_STAGE_TRANSFER_BIT |
                           VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                       0, 1, &barrier, 0, nullptr, 0, nullptr);
  m_image->record_init(cmd);  // recorded once per image, in the first frame that uses it
  m_outputs->record_init(cmd);
  const FrameWork work = m_structures->record(cmd);  // each structure build ends with a barrier for the trace
  m_bindings->record_upload(cmd);
  m_outputs->record_clear(cmd);
  record_trace(m_ctx, cmd, *m_pipeline, m_bindings->sets(), *m_sbt, width, height, m_bindings->push(), before, after);
  return work;
}

PROCEDURAY_DECL FrameWork Renderer::record(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) {
  prepare(width, height, "Renderer::record");
  return record_frame(cmd, width, height, {}, {});
}

PROCEDURAY_DECL FrameTicket Renderer::submit(std::uint32_t width, std::uint32_t height, Readback readback) {
  return submit_as(width, height, readback, "Renderer::submit");
}

PROCEDURAY_DECL FrameTicket Renderer::submit_as(std::uint32_t width, std::uint32_t height, Readback readback, std::string_view op) {
  prepare(width, height, op);
  FrameSlot& slot = m_ring->begin();
  const auto host_start = Clock::now();
  // The slot's record is written only once the frame is recorded: a frame that fails to record
  // leaves the slot's earlier frame as it was.
  Frame frame{width, height, {}, 0, 0, false, {}, {}};
  frame.work = record_frame(slot.cmd, width, height, {m_ring.get(), &slot, 0}, {m_ring.get(), &slot, 1});
  frame.tlas_refit = frame.work.tlas_builds + frame.work.tlas_updates > 0;
  if (readback != Readback::none) {
    const VkDeviceSize outputs = readback == Readback::all ? m_outputs->bytes() : 0;
    Buffer& buffer = m_ring->readback(slot, m_image->bytes() + outputs);
    m_image->record_copy(slot.cmd, buffer, 0);
    if (outputs > 0) m_outputs->record_copy(slot.cmd, buffer, m_image->bytes());
  }
  frame.host_ms = ms_since(host_start);
  SlotFrame& info = m_slot_frames[slot.index];
  info.frame = frame;
  info.readback = readback;
  info.timed = false;
  info.submitted = Clock::now();
  return {m_ring->submit(slot), m_serial};
}

PROCEDURAY_DECL Renderer::~Renderer() = default;

PROCEDURAY_DECL std::uint32_t Renderer::add_instance(GeometryId geometry, const glm::mat4& object_to_world,
                                                     std::uint32_t mask) {
  constexpr std::string_view op = "Renderer::add_instance";
  m_ring->wait_all();
  const SceneInstances& in = m_structures->instances();
  // Per-instance storage covers every custom index given so far; a reused one needs no more.
  const std::uint32_t count = std::max(in.next_custom_index() + 1, in.custom_index_bound());
  m_bindings->check_instance_count(count, op);  // throws before any change
  const std::uint32_t instance = m_structures->add_instance(geometry, object_to_world, mask, op);
  m_bindings->set_instance_count(count, op);
  if (m_structures->take_tlas_replaced()) m_bindings->write_tlas(m_structures->tlas().structure());
  return instance;
}

PROCEDURAY_DECL const StorageImage& Renderer::image() const {
  if (!m_image) throw UsageError("Renderer::image: no frame was traced yet; call render() or record() first");
  return *m_image;
}

PROCEDURAY_DECL double Renderer::warm_up() {
  const auto start = Clock::now();
  render(8, 8, false);
  return ms_since(start);
}

}  // namespace proceduray::vk

// Reading frames back: waiting for a frame, viewing or copying its pixels and outputs, and
// render(), which does both for one frame.
namespace proceduray::vk {

PROCEDURAY_DECL std::pair<FrameSlot*, Renderer::SlotFrame*> Renderer::finished(FrameTicket frame, std::string_view op) {
  check_ticket(frame, op);
  FrameSlot& slot = m_ring->slot_of(frame.number, op);
  m_ring->wait(slot);
  SlotFrame& info = m_slot_frames[slot.index];
  if (!info.timed) {
    info.frame.trace_ms = m_ctx.timestamp_period_ns() > 0 ? m_ring->trace_ms(slot) : ms_since(info.submitted);
    info.timed = true;
  }
  return {&slot, &info};
}

PROCEDURAY_DECL void Renderer::check_ticket(FrameTicket frame, std::string_view op) const {
  if (frame.renderer == m_serial) return;
  if (frame.renderer == 0) {
    throw UsageError(std::string(op) + ": ticket of frame " + std::to_string(frame.number) + " was not returned by "
                     "submit() (it names no renderer); pass the ticket this renderer's submit() returned");
  }
  throw UsageError(std::string(op) + ": ticket of frame " + std::to_string(frame.number) + " was issued by renderer #" +
                   std::to_string(frame.renderer) + ", not by this one (#" + std::to_string(m_serial) +
                   "); pass it to the renderer that submitted it");
}

PROCEDURAY_DECL Frame Renderer::wait(FrameTicket frame) { return finished(frame, "Renderer::wait").second->frame; }

PROCEDURAY_DECL std::span<const std::uint8_t> Renderer::rgba(FrameTicket frame) {
  auto [slot, info] = finished(frame, "Renderer::rgba");
  if (info->readback == Readback::none) {
    throw UsageError("Renderer::rgba: frame " + std::to_string(frame.number) +
                     " was submitted with Readback::none; submit it with Readback::rgba (the default) to read it");
  }
  const std::size_t bytes = std::size_t{info->frame.width} * info->frame.height * 4;
  return {static_cast<const std::uint8_t*>(slot->readback->data()), bytes};
}

PROCEDURAY_DECL void Renderer::read_rgba(FrameTicket frame, std::span<std::uint8_t> out) {
  const std::span<const std::uint8_t> pixels = rgba(frame);
  if (out.size() < pixels.size()) {
    const Frame& f = finished(frame, "Renderer::read_rgba").second->frame;
    throw UsageError("Renderer::read_rgba: the span holds " + std::to_string(out.size()) + " bytes but frame " +
                     std::to_string(frame.number) + " (" + std::to_string(f.width) + "x" + std::to_string(f.height) +
                     ") needs " + std::to_string(pixels.size()) + " (width * height * 4); give a span of at least that");
  }
  std::memcpy(out.data(), pixels.data(), pixels.size());
}

PROCEDURAY_DECL std::span<const std::uint8_t> Renderer::output_bytes(FrameTicket frame, Output which, std::string_view op) {
  auto [slot, info] = finished(frame, op);
  if (info->readback != Readback::all) {
    throw UsageError(std::string(op) + ": frame " + std::to_string(frame.number) +
                     " was not submitted with Readback::all; submit it so to read its outputs");
  }
  // The outputs follow the image, in the plan's order, each width * height pixels of its format.
  const std::size_t pixels = std::size_t{info->frame.width} * info->frame.height;
  std::size_t at = pixels * 4;
  for (const PlannedOutput& p : m_plan.outputs()) {
    const std::size_t bytes = pixels * storage_pixel_bytes(output_format(p.output));
    if (p.output == which) return {static_cast<const std::uint8_t*>(slot->readback->data()) + at, bytes};
    at += bytes;
  }
  throw UsageError(std::string(op) + ": the scene does not ask for output '" + std::string(proceduray::name(which)) +
                   "'; add it with Scene::set_outputs");
}

PROCEDURAY_DECL Frame Renderer::render(std::uint32_t width, std::uint32_t height, bool readback) {
  const FrameTicket ticket = submit_as(width, height, readback ? Readback::all : Readback::none, "Renderer::render");
  Frame frame = wait(ticket);
  if (readback) {
    const std::span<const std::uint8_t> pixels = rgba(ticket);
    frame.rgba.assign(pixels.begin(), pixels.end());
    if (!m_outputs->empty()) {
      frame.outputs = m_outputs->read(static_cast<const std::uint8_t*>(m_ring->slot_of(ticket.number, "Renderer::render")
                                                                          .readback->data()) + pixels.size());
    }
  }
  return frame;
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
