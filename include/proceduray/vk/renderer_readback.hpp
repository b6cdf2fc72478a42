// The bodies of a Renderer's reading frames back (declared in renderer.hpp, which includes this
// file): waiting for a frame, viewing or copying its pixels and outputs, and render(), which does
// both for one frame. Include renderer.hpp; this file only keeps that one under 400 lines.
//
//   proceduray::vk::FrameTicket t = renderer.submit(1024, 768);
//   std::span<const std::uint8_t> rgba = renderer.rgba(t);   // waits; mapped, host-cached memory
//   renderer.read_rgba(t, my_pixels);                         // or a copy
//   proceduray::vk::Frame f = renderer.render(1024, 768);     // submit, wait and copy, in one call
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/vk/renderer.hpp>

#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#if PROCEDURAY_BODIES

namespace proceduray::vk {

PROCEDURAY_DECL std::pair<FrameSlot*, Renderer::SlotFrame*> Renderer::finished(FrameTicket frame, std::string_view op) {
  FrameSlot& slot = m_ring->slot_of(frame.number, op);
  m_ring->wait(slot);
  SlotFrame& info = m_slot_frames[slot.index];
  if (!info.timed) {
    info.frame.trace_ms = m_ctx->timestamp_period_ns() > 0 ? m_ring->trace_ms(slot) : ms_since(info.submitted);
    info.timed = true;
  }
  return {&slot, &info};
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
    const Frame& f = m_slot_frames[m_ring->slot_of(frame.number, "Renderer::read_rgba").index].frame;
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
