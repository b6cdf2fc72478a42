// What the scene/ usage blocks take as given: the pure layers, the shared doc types, and a few
// values (a box, transforms, colours) named as the blocks name them.
#pragma once

#include <proceduray/scene/aabb_glsl.hpp>
#include <proceduray/scene/default_global_signature.hpp>
#include <proceduray/scene/glsl_for.hpp>
#include <proceduray/scene/object.hpp>
#include <proceduray/scene/placement.hpp>
#include <proceduray/scene/quad_mesh.hpp>
#include <proceduray/scene/sbt_printer.hpp>
#include <proceduray/scene/blas.hpp>
#include <proceduray/scene/scene.hpp>
#include <proceduray/scene/compile.hpp>
#include <proceduray/scene/glsl_files.hpp>
#include <proceduray/scene/uniform_slot.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstddef>
#include <iostream>
#include <span>
#include <vector>

#include "tests/docs/doc_types.hpp"

namespace doc_scene {
using namespace doc_types;
using DocScene = proceduray::Scene<DocInterface>;
using proceduray::ShaderStage;
using proceduray::GeometryDesc;
using proceduray::BindingKind;
inline const proceduray::Aabb box{glm::vec3(-1.0f), glm::vec3(1.0f)};
inline const std::vector<proceduray::InstanceTransform> transforms{proceduray::instance_transform(glm::mat4(1.0f))};
inline const proceduray::InstanceTransform left = proceduray::instance_transform(glm::mat4(1.0f));
inline const proceduray::InstanceTransform right = left;
inline const Material red{{1, 0, 0, 1}}, blue{{0, 0, 1, 1}};
inline constexpr proceduray::UniformSlot<SceneConstants> constants_slot{.binding = 2, .name = "constants"};
using BallHit = SphereHit;
using Sky = SkyArgs;
/// What the compile.hpp block compiles.
inline proceduray::Scene<DocInterface> make_scene() { return {}; }
}  // namespace doc_scene
