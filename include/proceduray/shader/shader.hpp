// The shader compatibility layer in one include: field lists, layout rules, categories, GLSL codegen.
//
//   #include <proceduray/shader/shader.hpp>
//   struct Hit { glm::vec3 normal; float t; };
//   PROCEDURAY_STRUCT(Hit, scalar, normal, t);
//   using Interface = proceduray::ShaderInterface<proceduray::Payload<Hit>, proceduray::RootComponent<>,
//                                                 proceduray::RootArguments<>, proceduray::Attributes<Hit>>;
//   std::string glsl = proceduray::glsl_declarations(Interface::types);
//
// Never includes Vulkan: everything here is pure C++ and glm.
#pragma once

#include <proceduray/shader/camera.hpp>
#include <proceduray/shader/categories.hpp>
#include <proceduray/shader/define_struct.hpp>
#include <proceduray/shader/device_address.hpp>
#include <proceduray/shader/field_list.hpp>
#include <proceduray/shader/glsl_codegen.hpp>
#include <proceduray/shader/glsl_consts.hpp>
#include <proceduray/shader/glsl_keywords.hpp>
#include <proceduray/shader/glsl_type.hpp>
#include <proceduray/shader/layout.hpp>
#include <proceduray/shader/layout_rule.hpp>
#include <proceduray/shader/lights.hpp>
#include <proceduray/shader/mesh_ref.hpp>
#include <proceduray/shader/value_check.hpp>
