// What a traced frame reports: its pixels, its times and the acceleration-structure work done
// before its trace; what a submitted frame copies back (Readback) and its ticket.
//
//   proceduray::vk::Frame frame = renderer.render(1024, 768);
//   frame.rgba;          // width * height RGBA8 pixels (empty without readback)
//   frame.trace_ms;      // GPU time of vkCmdTraceRaysKHR
//   frame.work == proceduray::vk::FrameWork{.tlas_updates = 1};   // a DynamicTransform frame
//   frame.outputs.t;     // per-pixel hit distances, when the scene asked for Output::t
#pragma once

#include <cstdint>
#include <vector>

namespace proceduray::vk {

/// What a submitted frame copies back for the host, in the frame's own command buffer.
enum class Readback {
  none,  ///< nothing: the frame stays on the device (Renderer::image() holds the last one)
  rgba,  ///< the RGBA8 image
  all,   ///< the image and every per-pixel output the scene asked for
};

/// A submitted frame: its number, 1, 2, ..., and the renderer that submitted it (Renderer::
/// serial()); what Renderer::wait, rgba and output take. Another renderer refuses it by name
/// rather than reading its own frame of that number.
struct FrameTicket {
  std::uint64_t number = 0;
  std::uint64_t renderer = 0;  ///< 0: not returned by a submit()
  friend bool operator==(const FrameTicket&, const FrameTicket&) = default;
};

/// Acceleration-structure work a frame did before its trace, as the update policies allowed.
struct FrameWork {
  std::uint32_t blas_builds = 0;   ///< DynamicGeometry BLASes rebuilt (topology changed)
  std::uint32_t blas_refits = 0;   ///< DynamicGeometry BLASes refit in place
  std::uint32_t tlas_builds = 0;   ///< TLAS rebuilt (a BLAS it references was rebuilt, or a mask changed)
  std::uint32_t tlas_updates = 0;  ///< TLAS refit (instances moved or a BLAS was refit)
  friend bool operator==(const FrameWork&, const FrameWork&) = default;
};

/// Per-pixel outputs read back (scene/outputs.hpp), rows top to bottom; an output the scene did
/// not ask for is empty.
struct Outputs {
  std::vector<float> t;                ///< width * height; -1 where nothing was written
  std::vector<float> normal;           ///< width * height * 4 (xyz, 0); 0 where nothing was written
  std::vector<std::uint32_t> ids;      ///< width * height * 4 (instance, geometry, primitive, 0); 0xffffffff: none
  std::vector<std::uint32_t> steps;    ///< width * height evaluation counts (summed)
  std::vector<std::uint32_t> flags;    ///< width * height output_flag_* bits (or-ed)
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
  Outputs outputs;          ///< per-pixel outputs, when the scene asks for any (with readback)
};

}  // namespace proceduray::vk
