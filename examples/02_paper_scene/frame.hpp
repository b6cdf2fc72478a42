// A paper frame as the measuring tools and tests vary it: the uniform, plus the fractals' march
// knobs, which the library owns (Renderer::set_field_knobs) and the ground truth reads.
//
//   paper::Frame f = paper::default_frame(320, 240, 0.0f);      // the scene's starting knobs
//   f.knobs[paper::mandelbulb_id].threshold = 2.0f;             // two footprints
//   paper::set_frame(renderer, f);                              // constants, pixel angle, knobs
//   paper::ReferenceImage truth = paper::reference_image(f, 320, 240);
#pragma once

#include "paper_scene.hpp"

#include <array>
#include <utility>

namespace paper {

/// Ids 0 .. object_id_count - 1: Frame::knobs has one entry per id.
inline constexpr std::uint32_t object_id_count = 6;

/// Marched objects and their names: the fields' ids (the sweep's and the accuracy tool's names).
inline constexpr std::pair<ObjectId, const char*> marched_objects[] = {{julia_id, "julia"}, {mandelbulb_id, "mandelbulb"}};

/// The knobs an object accepts, with the scene's starting knobs as the defaults (analytic
/// objects: none but the epsilon).
inline const pr::MarchCapabilities& capabilities(ObjectId id) {
  const auto fractal = [](const pr::MarchKnobs& starting) {
    pr::MarchCapabilities c = pr::fractal_capabilities(starting.iterations);
    c.defaults = starting;
    return c;
  };
  static const pr::MarchCapabilities julia = fractal(julia_knobs), bulb = fractal(mandelbulb_knobs);
  static const pr::MarchCapabilities analytic{"analytic", {}, {pr::MarchNormal::analytic}, 0, pr::march_base_knobs};
  return id == julia_id ? julia : (id == mandelbulb_id ? bulb : analytic);
}

/// The uniform and the knobs of every object (indexed by ObjectId; the fractals' are read).
struct Frame : SceneConstants {
  std::array<pr::MarchKnobs, object_id_count> knobs{};
};

/// default_constants with every object at its starting knobs.
inline Frame default_frame(std::uint32_t width, std::uint32_t height, float time) {
  Frame f{default_constants(width, height, time)};
  for (std::uint32_t id = 0; id < object_id_count; ++id) f.knobs[id] = capabilities(static_cast<ObjectId>(id)).defaults;
  return f;
}

/// Throws UsageError unless the fractals' knobs are valid (march/knobs.hpp's validate).
inline void validate_knobs(const Frame& f) {
  for (const auto& [id, name] : marched_objects) pr::validate(f.knobs[id], capabilities(id), name);
}

/// set_frame, then the fractals' knobs: each field by its id. Throws UsageError (naming
/// Renderer::set_field_knobs, the knob and the fix) for knobs a fractal does not accept.
inline void set_frame(pr::vk::Renderer& renderer, const Frame& f) {
  set_frame(renderer, static_cast<const SceneConstants&>(f));
  for (const pr::PlannedField& field : renderer.plan().fields()) {
    for (const auto& [id, name] : marched_objects) {
      if (field.field.id == name) renderer.set_field_knobs(field.geometry, f.knobs[id]);
    }
  }
}

}  // namespace paper
