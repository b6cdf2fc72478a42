// The distance fields' run-time settings on the device: one FieldSettings per field (its knobs
// and the view's pixel angle) in the storage buffer compile() declared (Plan::field_binding),
// checked on every change and uploaded before the next frame. The Renderer owns one.
//
//   proceduray::vk::FieldKnobs fields(plan, bindings);    // each field at its capabilities' defaults
//   fields.set_pixel_angle(camera.pixel_angle, "Renderer::set_pixel_angle");
//   fields.set(gyroid, knobs, "Renderer::set_field_knobs");   // throws UsageError: field, knob, range
//   fields.upload(bindings, "Renderer::render");              // throws until a pixel angle was given
//
// Why a pixel angle is required: footprint thresholds (the default) are a number of pixel
// footprints, pixel_angle * t; without it every threshold would fall to its epsilon floor and
// the march would run to the floor's precision, silently many times dearer.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/scene/plan.hpp>
#include <proceduray/vk/bindings.hpp>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray::vk {

/// The settings of a plan's distance fields, and their upload.
class FieldKnobs {
 public:
  /// Every field at its capabilities' defaults, written to `bindings` (none: nothing to do).
  FieldKnobs(const proceduray::Plan& plan, Bindings& bindings);

  /// Radians per pixel of the view (Camera::pixel_angle); throws UsageError unless finite and > 0.
  void set_pixel_angle(float radians, std::string_view op);
  /// Sets a field's knobs, checked against field_capabilities; throws UsageError naming `op`, the
  /// field and the knob, or for a geometry that is no distance field.
  void set(GeometryId field, const MarchKnobs& knobs, std::string_view op);
  /// A field's knobs now.
  const MarchKnobs& get(GeometryId field, std::string_view op) const;
  /// Writes changed settings to `bindings` (the caller makes sure no frame in flight reads them);
  /// throws UsageError, naming `op`, when the scene has fields and no pixel angle was given.
  void upload(Bindings& bindings, std::string_view op);
  /// True when a change waits for upload().
  bool dirty() const noexcept { return m_dirty; }
  /// Counts the knob changes (not the pixel angle's): a pipeline with the knobs compiled in
  /// (RendererOptions::specialize_fields) is stale when this moved.
  std::uint64_t version() const noexcept { return m_version; }
  /// Every field's knobs now, in Plan::fields() order.
  std::vector<MarchKnobs> knobs() const;
  /// Throws UsageError, naming `op` and the field, when an error budget's pick (Plan::fields())
  /// came from a table measured on another device than `device`, or for another text of the
  /// field's GLSL file than the one found in `dirs`: its errors were measured for something else.
  static void check_picks(const proceduray::Plan& plan, const std::string& device,
                          std::span<const std::filesystem::path> dirs, std::string_view op);

 private:
  std::size_t index(GeometryId field, std::string_view op) const;

  const proceduray::Plan* m_plan;
  std::vector<FieldSettings> m_settings;
  bool m_pixel_angle = false;
  bool m_dirty = false;
  std::uint64_t m_version = 0;
};

}  // namespace proceduray::vk

#include "proceduray/vk/field_knobs-inl.hpp"  // the bodies (config.hpp)
