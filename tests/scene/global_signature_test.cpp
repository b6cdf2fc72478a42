#include "proceduray/scene/global_signature.hpp"
#include "proceduray/scene/glsl_for.hpp"

#include <doctest/doctest.h>

#include "proceduray/scene/uniform_slot.hpp"
#include "proceduray/shader/field_list.hpp"

#include <glm/glm.hpp>

using namespace proceduray;

TEST_CASE("global_signature validate rejects duplicate bindings and odd push constants") {
  GlobalSignatureDesc ok{.bindings = {{.kind = BindingKind::acceleration_structure, .binding = 0},
                                      {.kind = BindingKind::storage_image, .binding = 1},
                                      {.kind = BindingKind::uniform_buffer, .binding = 0, .set = 1}},
                         .push_constant_size = 16};
  CHECK_NOTHROW(validate(ok, "G", "op"));
  GlobalSignatureDesc dup = ok;
  dup.bindings.push_back({.kind = BindingKind::storage_buffer, .binding = 1});
  CHECK_THROWS_WITH_AS(validate(dup, "G", "op"), doctest::Contains("op: global signature \"G\" declares set 0 binding 1 twice"),
                       DuplicateIdError);
  GlobalSignatureDesc odd = ok;
  odd.push_constant_size = 6;
  CHECK_THROWS_WITH_AS(validate(odd, "G", "op"), doctest::Contains("push_constant_size 6 is not a multiple of 4"), SceneError);
  GlobalSignatureDesc zero{.bindings = {{.count = 0}}};
  CHECK_THROWS_WITH_AS(validate(zero, "G", "op"), doctest::Contains("count 0"), SceneError);
  CHECK(std::string(to_string(BindingKind::storage_image)) == "storage_image");
}

namespace global_signature_test {
struct Knobs {
  glm::vec4 tint;
  float exposure;
  std::uint32_t frame;
  glm::vec2 pad;
};
PROCEDURAY_STRUCT(Knobs, scalar, tint, exposure, frame, pad);
}  // namespace global_signature_test

TEST_CASE("global_signature typed push constants set the size and exclude an untyped size") {
  using global_signature_test::Knobs;
  constexpr PushConstantSlot<Knobs> knobs{.name = "knobs"};
  GlobalSignatureDesc desc{.push_constants = knobs};
  CHECK(desc.push_bytes() == sizeof(Knobs));
  CHECK(desc.push_constants.name == "knobs");
  CHECK(desc.push_constants.type == &type_ops<Knobs>);
  CHECK_NOTHROW(validate(desc, "G", "op"));
  desc.push_constant_size = 16;
  CHECK_THROWS_WITH_AS(validate(desc, "G", "op"),
                       doctest::Contains("declares push_constant_size 16 and typed push constants (Knobs); declare one"),
                       SceneError);
  CHECK(GlobalSignatureDesc{.push_constant_size = 8}.push_bytes() == 8);
}

TEST_CASE("global_signature texture slots: arrays of 2D textures or cube maps, and arrays of nothing else") {
  constexpr TextureSlot grounds{.binding = 4, .set = 1, .name = "grounds", .count = 3};
  constexpr TextureSlot sky{.binding = 5, .name = "sky", .cube = true};
  const Binding g = grounds;
  CHECK(g.kind == BindingKind::sampled_image);
  CHECK(g.binding == 4);
  CHECK(g.set == 1);
  CHECK(g.count == 3);
  CHECK(g.name == "grounds");
  CHECK_FALSE(g.cube);
  CHECK(static_cast<Binding>(sky).cube);
  CHECK(std::string(to_string(BindingKind::sampled_image)) == "sampled_image");
  CHECK(detail::binding_glsl(g) == "layout(set = 1, binding = 4) uniform sampler2D grounds[3];\n");
  CHECK(detail::binding_glsl(sky) == "layout(set = 0, binding = 5) uniform samplerCube sky;\n");
  CHECK_NOTHROW(validate(GlobalSignatureDesc{.bindings = {grounds, sky}}, "G", "op"));
  GlobalSignatureDesc buffers{.bindings = {{.kind = BindingKind::storage_buffer, .binding = 0, .count = 2}}};
  CHECK_THROWS_WITH_AS(validate(buffers, "G", "op"),
                       doctest::Contains("binding 0 is storage_buffer with count 2; only textures (sampled_image) come "
                                         "in arrays"),
                       SceneError);
}
