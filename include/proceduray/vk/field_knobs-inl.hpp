// The bodies of proceduray/vk/field_knobs.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/field_knobs.hpp"

#include <cmath>
#include <cstring>

#include "proceduray/vk/scene_pipeline.hpp"
#include "proceduray/vk/shader_compiler.hpp"
#include <string>

#if PROCEDURAY_BODIES
namespace proceduray::vk {

namespace detail {
PROCEDURAY_DECL StorageSlot<FieldSettings> field_slot(const proceduray::Plan& plan) {
  return {.binding = plan.field_binding(), .name = field_settings_name};
}
}  // namespace detail

PROCEDURAY_DECL FieldKnobs::FieldKnobs(const proceduray::Plan& plan, Bindings& bindings) : m_plan(&plan) {
  for (const PlannedField& f : plan.fields()) m_settings.push_back({f.caps.defaults, 0.0f});
  if (!m_settings.empty()) bindings.set_storage(detail::field_slot(plan), std::span<const FieldSettings>(m_settings));
}

PROCEDURAY_DECL void FieldKnobs::set_pixel_angle(float radians, std::string_view op) {
  if (!(radians > 0.0f) || !std::isfinite(radians)) {
    throw UsageError(std::string(op) + ": pixel angle " + std::to_string(radians) + " must be a finite angle > 0 "
                     "(radians per pixel: Camera::pixel_angle, or the vertical field of view / the image height)");
  }
  const bool same = m_pixel_angle && !m_settings.empty() && m_settings[0].pixel_angle == radians;
  for (FieldSettings& s : m_settings) s.pixel_angle = radians;
  m_pixel_angle = true;
  m_dirty = m_dirty || (!m_settings.empty() && !same);
}

PROCEDURAY_DECL std::size_t FieldKnobs::index(GeometryId field, std::string_view op) const {
  const auto fields = m_plan->fields();
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (fields[i].geometry == field) return i;
  }
  std::string known;
  for (const PlannedField& f : fields) known += (known.empty() ? "\"" : ", \"") + f.field.id + "\"";
  throw UsageError(std::string(op) + ": geometry " + (field.valid() ? std::to_string(field.index()) : "(invalid)") +
                   " is no distance field of this scene; " +
                   (known.empty() ? std::string("it declares none (add_distance_field)")
                                  : "give one of its fields' ids (" + known + ")"));
}

PROCEDURAY_DECL void FieldKnobs::set(GeometryId field, const MarchKnobs& knobs, std::string_view op) {
  const std::size_t i = index(field, op);
  const PlannedField& f = m_plan->fields()[i];
  validate(knobs, f.caps, std::string(op) + ": field \"" + f.field.id + "\"");
  // Unchanged knobs (a frame loop setting them every frame) leave the buffer alone: a change
  // waits for the frames in flight.
  if (std::memcmp(&m_settings[i].knobs, &knobs, sizeof knobs) == 0) return;
  m_settings[i].knobs = knobs;
  m_dirty = true;
  ++m_version;
}

PROCEDURAY_DECL std::vector<MarchKnobs> FieldKnobs::knobs() const {
  std::vector<MarchKnobs> out;
  for (const FieldSettings& s : m_settings) out.push_back(s.knobs);
  return out;
}

PROCEDURAY_DECL const MarchKnobs& FieldKnobs::get(GeometryId field, std::string_view op) const {
  return m_settings[index(field, op)].knobs;
}

PROCEDURAY_DECL void FieldKnobs::upload(Bindings& bindings, std::string_view op) {
  if (m_settings.empty()) return;
  if (!m_pixel_angle) {
    throw UsageError(std::string(op) + ": the scene marches distance fields (\"" + m_plan->fields()[0].field.id +
                     "\"...) whose thresholds are pixel footprints; call Renderer::set_pixel_angle(camera.pixel_angle) "
                     "before the first frame");
  }
  if (!m_dirty) return;
  bindings.set_storage(detail::field_slot(*m_plan), std::span<const FieldSettings>(m_settings));
  m_dirty = false;
}

PROCEDURAY_DECL void FieldKnobs::check_picks(const proceduray::Plan& plan, const std::string& device,
                                             std::span<const std::filesystem::path> dirs, std::string_view op) {
  for (const PlannedField& f : plan.fields()) {
    if (!f.pick) continue;
    const std::string where = std::string(op) + ": distance field \"" + f.field.id + "\"";
    if (f.pick_device != device) {
      throw UsageError(where + ": its error budget's table was measured on " + f.pick_device + ", this device is " +
                       device + "; calibrate on this device (vk::calibrate) and pass that table");
    }
    if (f.pick_source.empty()) continue;  // a table that does not say what it measured
    const std::string now = field_source(f.field, read_text_file(find_shader(dirs, f.field.glsl)));
    if (f.pick_source != now) {
      throw UsageError(where + ": its error budget's table was measured for '" + f.pick_source + "', the file is now '" +
                       now + "'; calibrate it again (vk::calibrate reads its cache only for the same text)");
    }
  }
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
