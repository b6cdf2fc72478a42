// A distance field as the scene and the plan keep it: the user's GLSL function, its box and its
// Lipschitz bound, and the intersection shader the library writes for it from its own marchers.
// Declared with add_distance_field (distance_field.hpp); this header is what compile() and the
// renderer read.
//
//   proceduray::DistanceField f{.id = "gyroid", .glsl = "gyroid.glsl", .function = "gyroid_distance",
//                               .aabb = box, .lipschitz = 1.8f};
//   proceduray::validate(f, "add_distance_field");       // throws UsageError naming the value and the fix
//   proceduray::MarchCapabilities caps = proceduray::field_capabilities(f);   // no sphere steps: L > 1
//   std::string rint = proceduray::field_stage_source(f, 0);   // the generated intersection shader
//
// The GLSL file holds `pr_real <function>(pr_real3 p)` (a fractal: `(pr_real3 p, uint iterations)`),
// then one argument per declared parameter (field_parameter: a member of a scene uniform, read
// per frame, such as an animation's time), in the portable subset. A field whose normal is known
// exactly somewhere (a cut face, where differences of max(f, plane) tilt) names a function
// `bool <normal>(pr_real3 p[, uint iterations][, parameters...], PROCEDURAY_OUT(pr_real3) n)`:
// true where n (unit, outward, object space) is exact; elsewhere the library takes differences.
// All of it of shader/glsl_cpp.hpp, so the same file compiles as C++ for the ground
// truth. f(p) <= 0 inside; |f(p) - f(q)| <= L |p - q| with L the declared bound (1 when exact).
// The generated shader passes L to march_settings: lipschitz and relaxed steps are f / L, and
// plain sphere steps (which take the distance as it is, assuming L = 1) are refused where L > 1.
//
// Knobs: one FieldSettings per field in a library storage buffer (`proceduray_fields`, a binding
// compile() adds after the global signature's and the outputs'), written by the renderer
// (Renderer::set_field_knobs, set_pixel_angle): the same MarchKnobs every marched geometry takes.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/march/calibration.hpp>
#include <proceduray/march/knobs.hpp>
#include <proceduray/scene/geometry.hpp>
#include <proceduray/scene/ids.hpp>
#include <proceduray/scene/shader_stage.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/shader/define_struct.hpp>

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace proceduray {

/// What a distance field's intersection shader reports (hitAttributeEXT `hit`): list it in the
/// scene interface's Attributes<...> to declare distance fields.
PROCEDURAY_DEFINE_STRUCT(FieldHit, scalar,
    (glm::vec3, normal),   ///< object space, unit, outward (the field's gradient)
    (float, steps),        ///< distance evaluations the march took (the normal's not included)
    (float, threshold));   ///< world units: the hit lies within this of the surface (the knobs'
                           ///< threshold at its t); start secondary rays twice as far out

/// One field's run-time settings (the `proceduray_fields` storage buffer, one per field).
PROCEDURAY_DEFINE_STRUCT(FieldSettings, scalar,
    (MarchKnobs, knobs),   ///< how the field is marched
    (float, pixel_angle)); ///< radians per pixel: footprint thresholds scale with it

/// The GLSL instance name of the field settings buffer (reserved: the proceduray_ prefix).
inline constexpr const char* field_settings_name = "proceduray_fields";

/// A value a distance function takes after the point (and the iterations), read where the field
/// is evaluated, so it changes without a pipeline rebuild: a member of a uniform the scene's
/// global signature declares (per frame: an animation's time, a cut plane), or of the field's hit
/// record (per instance block: a size, a twist). Made by field_parameter, so the argument's type
/// is the member's; compile() checks the uniform is declared, add_distance_field that the records
/// are of that type.
struct FieldParameter {
  std::string block;                    ///< the uniform's GLSL instance name (UniformSlot::name), or "arguments"
  const TypeOps* block_type = nullptr;  ///< what the uniform or the record holds
  std::string member;                   ///< the member passed, by name
  const TypeOps* type = nullptr;        ///< the member's type
  bool record = false;                  ///< true: a member of the field's hit record
  friend bool operator==(const FieldParameter&, const FieldParameter&) = default;
};

namespace detail {
/// The registered member of S that `member` points to, as a parameter read from `block`.
template <RegisteredStruct S, class M>
FieldParameter member_parameter(std::string block, M S::*member, bool record) {
  const S probe{};
  const auto offset = static_cast<std::size_t>(reinterpret_cast<const char*>(&(probe.*member)) -
                                               reinterpret_cast<const char*>(&probe));
  const TypeOps& s = type_ops<S>;
  for (std::size_t i = 0; i < s.field_count; ++i) {
    if (s.fields[i].offset == offset && s.fields[i].type == &type_ops<M>) {
      return {std::move(block), &s, std::string(s.fields[i].name), &type_ops<M>, record};
    }
  }
  throw UsageError("field_parameter: the member at byte " + std::to_string(offset) + " of " + std::string(s.glsl_name) +
                   " is not one of its registered members; register it (PROCEDURAY_STRUCT) or pass another");
}
}  // namespace detail

/// The parameter `slot.name.<member>`: `field_parameter(constants_slot, &Constants::time)`.
/// Throws UsageError for a slot without a GLSL name (it is declared by hand, so no generated
/// shader can name it).
template <RegisteredStruct S, class M>
FieldParameter field_parameter(const UniformSlot<S>& slot, M S::*member) {
  const std::string uniform = slot.name == nullptr ? "" : slot.name;
  if (uniform.empty()) {
    throw UsageError(std::string("field_parameter: the uniform of ") + std::string(type_ops<S>.glsl_name) +
                     " has no GLSL name; give its UniformSlot a .name so the generated shader can read it");
  }
  return detail::member_parameter(uniform, member, false);
}

/// The parameter `arguments.<member>` of the field's hit record (its instance block's):
/// `field_parameter(record_signature, &Record::scale)`; the field's records must be R's.
template <class R, class M>
FieldParameter field_parameter(LocalSignatureId<R>, M R::*member) {
  return detail::member_parameter("arguments", member, true);
}

/// A distance field: what add_distance_field records and compile() plans.
struct DistanceField {
  std::string id;                ///< the object's id: geometry and hit groups
  std::string glsl;              ///< the file holding the function, found in the shader folders
  std::string function;          ///< its name; empty: "<id>_distance"
  Aabb aabb;                     ///< local bounds; the surface lies inside
  float lipschitz = 0.0f;        ///< the bound L (> 0); exact fields: 1
  bool exact = false;            ///< f is an exact distance (L = 1)
  std::uint32_t iterations = 0;  ///< > 0: a fractal, f(p, iterations), with this default count
  std::vector<FieldParameter> parameters;  ///< passed after p (and iterations), in order
  std::optional<MarchKnobs> knobs;         ///< its starting knobs; none: field_capabilities' defaults
  std::string normal;                      ///< a function giving the exact normal where it knows it; empty: none
  friend bool operator==(const DistanceField& a, const DistanceField& b) {
    const auto same_knobs = [](const std::optional<MarchKnobs>& x, const std::optional<MarchKnobs>& y) {
      return x.has_value() == y.has_value() && (!x || std::memcmp(&*x, &*y, sizeof(MarchKnobs)) == 0);
    };
    return a.id == b.id && a.glsl == b.glsl && a.function == b.function && a.aabb == b.aabb &&
           a.lipschitz == b.lipschitz && a.exact == b.exact && a.iterations == b.iterations &&
           a.parameters == b.parameters && same_knobs(a.knobs, b.knobs) && a.normal == b.normal;
  }
};

/// An error budget for the fields, with the calibration it is met from and the frame size that
/// calibration must have been measured at (Scene::set_error_budget).
struct FieldBudget {
  ErrorBudget budget;
  Calibration table;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};

/// The cheapest row of `table` for field `f` that meets `budget` and that `f` accepts (rows of
/// a method it refuses, such as sphere steps past L = 1, never count), for width x height
/// frames. Throws UsageError naming `op` and the field: a table of another size (both sizes,
/// and the fix), no rows for it (calibrate it), or no row meeting the budget (the best reachable).
PROCEDURAY_DECL CalibrationRow pick_setting(const DistanceField& f, const FieldBudget& b, std::string_view op);

/// What a field's calibration records as its source (Calibration::source): "<id> glsl <FNV-1a
/// of the file's text>", so a table is not reused for another version of the file.
PROCEDURAY_DECL std::string field_source(const DistanceField& f, std::string_view glsl_text);

/// The function's name: DistanceField::function, or "<id>_distance".
PROCEDURAY_DECL std::string field_function(const DistanceField& f);

/// The bound the march divides by: 1 when exact, else DistanceField::lipschitz.
inline float field_lipschitz(const DistanceField& f) { return f.exact ? 1.0f : f.lipschitz; }

/// Throws UsageError, naming `op`, the field, the value and the fix: an empty or non-GLSL file
/// name, a function name that is no identifier, a non-finite or inverted AABB, a bound <= 0, NaN
/// or infinite (or missing and not exact), iterations past march_max_iterations_limit, a
/// parameter without a uniform or member name, starting knobs the field does not accept.
PROCEDURAY_DECL void validate(const DistanceField& f, std::string_view op);

/// What the field accepts: every method of march/ but plain sphere steps where L > 1 (they take
/// the distance as it is and overshoot), difference normals, iterations when a fractal; the
/// defaults are the field's starting knobs, else march_base_knobs (a fractal's iterations its own).
PROCEDURAY_DECL MarchCapabilities field_capabilities(const DistanceField& f);

/// The first specialization constant id of a generated field stage: a bool (specialized or not),
/// then one per MarchKnobs member in declaration order (field_spec_constants). Far above the ids
/// a user's own GLSL would pick, below glslang's limit (2047).
inline constexpr std::uint32_t field_spec_id = 2000;

/// The constants that compile `knobs` into a generated field stage: field_spec_id = true, then
/// each member's bits. Without them (a general stage) the shader reads the knobs from
/// `proceduray_fields` on every ray, so they change without a new pipeline.
PROCEDURAY_DECL std::vector<SpecConstant> field_spec_constants(const MarchKnobs& knobs);

/// The name of the field's generated intersection stage: "<id>.field.rint" (no file has it).
PROCEDURAY_DECL std::string field_stage_name(const DistanceField& f);

/// The intersection shader of field number `index` (proceduray_fields.data[index]): includes the
/// user's file and marching/field.glsl, generates the marcher (marching/marcher.glsl) for f,
/// marches with the bound, takes the normal and reports FieldHit. Its knobs are specialization
/// constants (field_spec_constants) when given, else the buffer's: one SPIR-V for both variants.
/// Why constants: the driver folds the methods a field does not use out of its hit group, so the
/// pipeline compiles one march per field instead of every method of march/, and runs fewer branches.
PROCEDURAY_DECL std::string field_stage_source(const DistanceField& f, std::uint32_t index);

}  // namespace proceduray

#include "proceduray/scene/field-inl.hpp"  // the bodies (config.hpp)
