// The bodies of proceduray/scene/field.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/field.hpp"

#include <cmath>

#include "proceduray/error.hpp"
#include "proceduray/scene/glsl_names.hpp"
#include "proceduray/shader/glsl_codegen.hpp"
#include "proceduray/shader/glsl_keywords.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {


PROCEDURAY_DECL std::string field_function(const DistanceField& f) { return f.function.empty() ? f.id + "_distance" : f.function; }

PROCEDURAY_DECL void validate(const DistanceField& f, std::string_view op) {
  const std::string where = std::string(op) + ": distance field \"" + f.id + "\"";
  auto fail = [&](const std::string& what) { throw UsageError(where + ": " + what); };
  if (f.glsl.empty()) {
    fail("names no GLSL file; set .glsl to the file holding its distance function (found in RendererOptions::shader_dirs)");
  }
  if (f.glsl.find_first_of("\"\n\r") != std::string::npos) {
    fail("GLSL file name '" + f.glsl + "' holds a quote or a line break; give a plain path");
  }
  const std::string function = field_function(f);
  if (function.empty() || glsl_identifier(function) != function || is_glsl_reserved(function) || function.starts_with("gl_") ||
      function.starts_with("proceduray_")) {
    fail("function '" + function + "' is no GLSL function name (letters, digits, _; not reserved, not gl_ or "
         "proceduray_); set .function to the name in " + f.glsl);
  }
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(f.aabb.min[a]) || !std::isfinite(f.aabb.max[a])) {
      fail("AABB axis " + std::to_string(a) + " is [" + detail::number(f.aabb.min[a]) + ", " +
           detail::number(f.aabb.max[a]) + "], not finite; give finite local bounds around the surface");
    }
    if (!(f.aabb.min[a] < f.aabb.max[a])) {
      fail("AABB axis " + std::to_string(a) + " is [" + detail::number(f.aabb.min[a]) + ", " +
           detail::number(f.aabb.max[a]) + "]: min must be below max; swap them or widen the box");
    }
  }
  if (f.exact) {
    if (f.lipschitz != 0.0f && f.lipschitz != 1.0f) {
      fail("is declared exact (L = 1) and gives lipschitz " + detail::number(f.lipschitz) +
           "; drop .exact or the bound");
    }
  } else if (!(f.lipschitz > 0.0f) || !std::isfinite(f.lipschitz)) {
    fail(f.lipschitz == 0.0f
             ? std::string("has no Lipschitz bound; give .lipschitz (the largest |grad f|: e.g. 1.8 for a gyroid "
                           "shell), or set .exact = true for an exact distance")
             : "Lipschitz bound " + detail::number(f.lipschitz) +
                   " must be a finite number > 0: the largest |grad f| over the box (.exact = true for an exact "
                   "distance)");
  }
  if (f.iterations > march_max_iterations_limit) {
    fail("iterations " + std::to_string(f.iterations) + " is past the limit " +
         std::to_string(march_max_iterations_limit) + "; give 1 to " + std::to_string(march_max_iterations_limit) +
         " (0: not a fractal)");
  }
  if (!f.normal.empty() && (glsl_identifier(f.normal) != f.normal || is_glsl_reserved(f.normal) ||
                            f.normal.starts_with("gl_") || f.normal.starts_with("proceduray_") || f.normal == function)) {
    fail("normal function '" + f.normal + "' is no GLSL function name of its own (letters, digits, _; not reserved, "
         "not gl_ or proceduray_, not the distance function); set .normal to the name in " + f.glsl + " or leave it empty");
  }
  for (const FieldParameter& p : f.parameters) {
    if (p.block.empty() || p.member.empty() || p.type == nullptr || p.block_type == nullptr) {
      fail("has a parameter without a uniform or a member ('" + p.block + "." + p.member +
           "'); make each with field_parameter(slot, &Struct::member)");
    }
  }
  if (f.knobs) {
    DistanceField plain = f;
    plain.knobs.reset();
    validate(*f.knobs, field_capabilities(plain), where + " starting knobs");
  }
}

PROCEDURAY_DECL MarchCapabilities field_capabilities(const DistanceField& f) {
  MarchCapabilities caps{f.iterations > 0 ? "fractal field" : "distance field", {}, {}, 0, march_base_knobs};
  caps.methods = {MarchMethod::lipschitz, MarchMethod::relaxed, MarchMethod::fixed};
  // Plain sphere steps take the distance as it is: safe only when it is 1-Lipschitz.
  if (field_lipschitz(f) <= 1.0f) caps.methods.insert(caps.methods.begin() + 1, MarchMethod::sphere);
  caps.normals = {MarchNormal::central, MarchNormal::tetrahedral};
  if (f.iterations > 0) {
    caps.max_iterations = march_max_iterations_limit;
    caps.defaults.iterations = f.iterations;
  }
  if (f.knobs) caps.defaults = *f.knobs;  // checked by validate(DistanceField)
  return caps;
}

PROCEDURAY_DECL CalibrationRow pick_setting(const DistanceField& f, const FieldBudget& b, std::string_view op) {
  const std::string where = std::string(op) + ": distance field \"" + f.id + "\"";
  const std::string size = std::to_string(b.width) + "x" + std::to_string(b.height);
  if (b.table.size() != size) {
    throw UsageError(where + ": the calibration was measured at " + b.table.size() + ", the frames are " + size +
                     "; errors in footprints grow with the resolution, so calibrate at " + size +
                     " (vk::calibrate with a view of that size)");
  }
  const MarchCapabilities caps = field_capabilities(f);
  std::vector<CalibrationRow> usable;
  std::size_t rows = 0;
  for (const CalibrationRow& r : b.table.rows()) {
    if (r.geometry != f.id) continue;
    ++rows;
    try {
      validate(r.knobs, caps, f.id);
      usable.push_back(r);
    } catch (const UsageError&) {
      // a setting the field refuses (e.g. sphere steps past L = 1) is never picked
    }
  }
  if (usable.empty()) {
    throw UsageError(where + ": the calibration has " + (rows == 0 ? std::string("no rows for it") :
                     std::to_string(rows) + " rows for it, none a setting it accepts") +
                     "; calibrate it (vk::calibrate) and pass that table");
  }
  try {
    return Calibration(b.table.device(), b.table.size(), std::move(usable)).cheapest(f.id, b.budget);
  } catch (const UsageError& e) {
    throw UsageError(std::string(op) + ": " + e.what());
  }
}

PROCEDURAY_DECL std::string field_source(const DistanceField& f, std::string_view glsl_text) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a
  for (unsigned char c : glsl_text) h = (h ^ c) * 1099511628211ull;
  static constexpr char digits[] = "0123456789abcdef";
  std::string hex(16, '0');
  for (int i = 15; i >= 0; --i, h >>= 4) hex[static_cast<std::size_t>(i)] = digits[h & 15u];
  return f.id + " glsl " + hex;
}

PROCEDURAY_DECL std::string field_stage_name(const DistanceField& f) { return f.id + ".field.rint"; }

namespace detail {
/// MarchKnobs' members as specialization constants (ids field_spec_id + 1...) and the knobs they
/// make when field_spec_id is set: generated from the registered struct, so a new knob is a
/// constant without an edit here.
inline std::string field_spec_declarations() {
  const TypeOps& t = type_ops<MarchKnobs>;
  std::string s = "layout(constant_id = " + std::to_string(field_spec_id) + ") const bool proceduray_knobs_specialized = false;\n";
  std::string body;
  for (std::size_t i = 0; i < t.field_count; ++i) {
    const Field& m = t.fields[i];
    const std::string name = "proceduray_knob_" + std::string(m.name);
    const bool real = m.type->glsl_name == "float";
    s += "layout(constant_id = " + std::to_string(field_spec_id + 1 + i) + ") const " + std::string(m.type->glsl_name) +
         " " + name + " = " + (real ? "0.0" : "0u") + ";\n";
    body += "  k." + std::string(m.name) + " = " + name + ";\n";
  }
  s += "MarchKnobs proceduray_field_knobs(MarchKnobs general) {\n";
  s += "  if (!proceduray_knobs_specialized) return general;\n";
  s += "  MarchKnobs k;\n" + body + "  return k;\n}\n";
  return s;
}
}  // namespace detail

PROCEDURAY_DECL std::vector<SpecConstant> field_spec_constants(const MarchKnobs& knobs) {
  const TypeOps& t = type_ops<MarchKnobs>;
  std::vector<SpecConstant> out{{field_spec_id, 1u}};
  for (std::size_t i = 0; i < t.field_count; ++i) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, reinterpret_cast<const char*>(&knobs) + t.fields[i].offset, sizeof bits);
    out.push_back({field_spec_id + 1 + static_cast<std::uint32_t>(i), bits});
  }
  return out;
}

PROCEDURAY_DECL std::string field_stage_source(const DistanceField& f, std::uint32_t index) {
  const std::string n = std::to_string(index);
  const std::string distance = "proceduray_field" + n;
  const std::string marcher = "proceduray_march" + n;
  // The parameters are read from their uniforms where the field is evaluated: per frame, no rebuild.
  std::string arguments = f.iterations > 0 ? "p, iterations" : "p";
  for (const FieldParameter& p : f.parameters) arguments += ", " + p.block + "." + p.member;
  const std::string call = field_function(f) + "(" + arguments + ")";
  std::string s;
  s += "#version 460\n";
  s += "// Generated by proceduray for the distance field \"" + f.id + "\" (scene/field.hpp).\n";
  s += "#include \"marching/field.glsl\"\n";
  s += "#include \"" + f.glsl + "\"\n";
  s += glsl_const(distance + "_box_min", f.aabb.min);
  s += glsl_const(distance + "_box_max", f.aabb.max);
  s += glsl_const(distance + "_lipschitz", field_lipschitz(f));
  s += "float " + distance + "(vec3 p, uint iterations) {\n  return " + call + ";\n}\n";
  s += "#define PROCEDURAY_MARCHER " + marcher + "\n";
  s += "#define PROCEDURAY_MARCHER_FIELD uint\n";
  s += "#define PROCEDURAY_MARCHER_DISTANCE " + distance + "\n";
  s += "#include \"marching/marcher.glsl\"\n";
  s += detail::field_spec_declarations();
  s += "void main() {\n";
  s += "  FieldSettings f = " + std::string(field_settings_name) + ".data[" + n + "];\n";
  s += "  f.knobs = proceduray_field_knobs(f.knobs);\n";
  s += "  FieldMarch fm;\n";
  // lipschitz and relaxed steps divide by the bound; sphere steps (only where L <= 1) do not.
  s += "  if (!field_march_begin(" + distance + "_box_min, " + distance + "_box_max, f.knobs, f.pixel_angle, " +
       distance + "_lipschitz, fm)) return;\n";
  s += "  uint iterations = march_iterations(f.knobs, fm.footprint);\n";
  s += "#ifdef PROCEDURAY_OUTPUTS\n";
  s += "  field_march_started(" + distance + "(fm.o + fm.range.x * fm.u, iterations));\n";
  s += "#endif\n";
  s += "  float s;\n  uint steps;\n";
  s += "  bool found = " + marcher + "_trace(fm.o, fm.u, fm.range.x, fm.range.y, fm.m, iterations, s, steps);\n";
  s += "  vec3 p = fm.o + s * fm.u;\n";
  s += "  bool normal = found && !field_hit_only();  // a shadow ray reads no normal\n";
  const std::string differences = marcher + "_normal(uint(f.knobs.normal), p, field_normal_offset(f.knobs, fm.m, p, s), "
                                  "iterations)";
  if (f.normal.empty()) {
    s += "  vec3 n = normal ? " + differences + " : vec3(0.0, 1.0, 0.0);\n";
  } else {  // the user's exact normal where it knows one (iterations as the march used them)
    s += "  vec3 n = vec3(0.0, 1.0, 0.0);\n";
    s += "  if (normal && !" + f.normal + "(" + arguments + ", n)) n = " + differences + ";\n";
  }
  s += "  field_march_report(found, s / fm.len, steps, fm.m, n, normal ? march_normal_evaluations(f.knobs) : 0u);\n";
  s += "}\n";
  return s;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
