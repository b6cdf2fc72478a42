// What the vk/ usage blocks take as given: the library, the shared doc types, and a few values
// named as the blocks name them.
#pragma once

#include <proceduray/proceduray.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tests/docs/doc_types.hpp"

namespace doc_vk {
using namespace doc_types;
using DocScene = proceduray::Scene<DocInterface>;
using proceduray::SbtRegionKind;
using proceduray::BindingKind;
using proceduray::layout_sbt;
using proceduray::vk::ShaderStage;
using proceduray::vk::ShaderGroup;
using proceduray::vk::compile_glsl;
using proceduray::Camera;
using Colour = Material;
inline const Material red{{1, 0, 0, 1}}, blue{{0, 0, 1, 1}};
inline constexpr proceduray::UniformSlot<SceneConstants> constants_slot{.binding = 2, .name = "constants"};
inline constexpr proceduray::StorageSlot<Tint> tints_slot{.binding = 3, .name = "tints"};
inline constexpr proceduray::PushConstantSlot<FrameKnobs> knobs_slot{.name = "knobs"};
/// What a block that builds a scene elsewhere calls.
inline proceduray::Scene<DocInterface> make_scene() { return {}; }
/// A scene as the examples write one (a proceduray::Scene<Interface> with renderer_options).
struct MyScene : proceduray::Scene<DocInterface> {
  proceduray::vk::RendererOptions renderer_options(const std::string&) const { return {}; }
};
}  // namespace doc_vk
