// The images of a scene's per-pixel outputs (scene/outputs.hpp): one per output the plan lists,
// bound to its binding, cleared before every trace, read back into a Frame's `outputs`.
//
//   proceduray::vk::OutputImages outputs(ctx, plan.outputs());
//   outputs.resize(width, height, bindings);           // makes and binds the images for this size
//   ctx.submit([&](VkCommandBuffer cmd) { outputs.record_init(cmd); outputs.record_clear(cmd); /* trace */ });
//   proceduray::vk::Outputs read = outputs.read();     // read.t: width * height floats, -1 where nothing hit
//   outputs.record_copy(frame_cmd, readback, offset);  // or copy them in the frame, then, after its fence,
//   proceduray::vk::Outputs same = outputs.read(static_cast<const std::uint8_t*>(readback.data()) + offset);
//
// Images made by resize() reach the general layout through record_init(cmd), in the frame.
//
// Renderer does all of this when the scene asks for outputs; a scene that asks for none gets no image.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/scene/entry.hpp>
#include <proceduray/scene/outputs.hpp>
#include <proceduray/vk/bindings.hpp>
#include <proceduray/vk/frame.hpp>
#include <proceduray/vk/storage_image.hpp>

#include <cstdint>
#include <cstring>
#include <utility>
#include <memory>
#include <span>
#include <vector>

namespace proceduray::vk {

/// What an output's image is cleared to before a trace: the value of "nothing written".
PROCEDURAY_DECL VkClearColorValue output_clear_value(Output o);

/// The Vulkan format of an output's image (format_of(o) in GLSL terms).
PROCEDURAY_DECL VkFormat output_format(Output o);

/// One storage image per planned output.
class OutputImages {
 public:
  /// `depth_binding`: Plan::depth_binding(), the depth counter's image, or no_index. The library's
  /// own: cleared to level 1 once when made (so a raw traceRayEXT in raygen counts as level 1),
  /// then kept there by the trace functions, never copied or read on the host.
  OutputImages(const Context& ctx, std::span<const PlannedOutput> planned, std::uint32_t depth_binding = no_index)
      : m_ctx(&ctx), m_planned(planned.begin(), planned.end()), m_depth_binding(depth_binding) {}

  /// Makes the images for width x height (when the size changed) and binds them in `bindings`.
  void resize(std::uint32_t width, std::uint32_t height, Bindings& bindings) {
    if ((m_planned.empty() && m_depth_binding == no_index) || (m_width == width && m_height == height)) return;
    m_images.clear();
    for (const PlannedOutput& p : m_planned) {
      m_images.push_back(
          std::make_unique<StorageImage>(*m_ctx, width, height, output_format(p.output), StorageImage::recorded));
      bindings.bind_output(p.binding, m_images.back()->view());
    }
    if (m_depth_binding != no_index) {
      m_depth = std::make_unique<StorageImage>(*m_ctx, width, height, VK_FORMAT_R32_UINT, StorageImage::recorded);
      bindings.bind_output(m_depth_binding, m_depth->view());
      m_depth_fresh = true;
    }
    m_width = width;
    m_height = height;
  }
  /// Records the layout transitions of images resize() made (nothing for those done before).
  void record_init(VkCommandBuffer cmd) {
    for (auto& image : m_images) image->record_init(cmd);
    if (m_depth && m_depth_fresh) {
      m_depth->record_init(cmd);
      m_depth->record_clear(cmd, VkClearColorValue{.uint32 = {1u, 0u, 0u, 0u}});
      m_depth_fresh = false;
    }
  }
  /// Bytes of all the images, packed one after another in the planned order.
  VkDeviceSize bytes() const noexcept {
    VkDeviceSize n = 0;
    for (const auto& image : m_images) n += image->bytes();
    return n;
  }
  /// Records copies of every image to `buffer` from `offset` on, one after another (bytes() in all).
  void record_copy(VkCommandBuffer cmd, const Buffer& buffer, VkDeviceSize offset) const {
    for (const auto& image : m_images) {
      image->record_copy(cmd, buffer, offset);
      offset += image->bytes();
    }
  }
  /// The outputs out of memory that record_copy filled (mapped, after the frame's fence).
  Outputs read(const std::uint8_t* copied) const {
    Outputs out;
    for (std::size_t i = 0; i < m_images.size(); ++i) {
      const std::size_t n = static_cast<std::size_t>(m_images[i]->bytes()) / 4;
      switch (m_planned[i].output) {
        case Output::t: out.t.resize(n); std::memcpy(out.t.data(), copied, n * 4); break;
        case Output::normal: out.normal.resize(n); std::memcpy(out.normal.data(), copied, n * 4); break;
        case Output::ids: out.ids.resize(n); std::memcpy(out.ids.data(), copied, n * 4); break;
        case Output::steps: out.steps.resize(n); std::memcpy(out.steps.data(), copied, n * 4); break;
        case Output::flags: out.flags.resize(n); std::memcpy(out.flags.data(), copied, n * 4); break;
      }
      copied += m_images[i]->bytes();
    }
    return out;
  }
  /// Where output `o` starts in what record_copy wrote and its bytes; {0, 0} when not planned.
  std::pair<VkDeviceSize, VkDeviceSize> range(Output o) const noexcept {
    VkDeviceSize at = 0;
    for (std::size_t i = 0; i < m_images.size(); ++i) {
      if (m_planned[i].output == o) return {at, m_images[i]->bytes()};
      at += m_images[i]->bytes();
    }
    return {0, 0};
  }
  /// Records the clears that make every pixel "nothing written" before a trace.
  void record_clear(VkCommandBuffer cmd) const {
    for (std::size_t i = 0; i < m_images.size(); ++i) m_images[i]->record_clear(cmd, output_clear_value(m_planned[i].output));
  }
  /// Reads every output back (waits for the queue).
  Outputs read() const {
    Outputs out;
    for (std::size_t i = 0; i < m_images.size(); ++i) {
      const StorageImage& image = *m_images[i];
      switch (m_planned[i].output) {
        case Output::t: out.t = image.read_as<float>(); break;
        case Output::normal: out.normal = image.read_as<float>(); break;
        case Output::ids: out.ids = image.read_as<std::uint32_t>(); break;
        case Output::steps: out.steps = image.read_as<std::uint32_t>(); break;
        case Output::flags: out.flags = image.read_as<std::uint32_t>(); break;
      }
    }
    return out;
  }
  bool empty() const noexcept { return m_planned.empty(); }

 private:
  const Context* m_ctx;
  std::vector<PlannedOutput> m_planned;
  std::vector<std::unique_ptr<StorageImage>> m_images;  // m_planned's order
  std::uint32_t m_depth_binding = no_index;
  std::unique_ptr<StorageImage> m_depth;  // the depth counter's, when planned
  bool m_depth_fresh = false;             // made by resize(), not yet initialised
  std::uint32_t m_width = 0, m_height = 0;
};

}  // namespace proceduray::vk

#include "proceduray/vk/output_images-inl.hpp"  // the bodies (config.hpp)
