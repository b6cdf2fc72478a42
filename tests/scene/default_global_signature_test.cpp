// Tests for proceduray/scene/default_global_signature.hpp: the TLAS and image bindings, then the scene's own.
#include "proceduray/scene/default_global_signature.hpp"

#include "proceduray/scene/scene.hpp"
#include "proceduray/scene/uniform_slot.hpp"
#include "proceduray/shader/field_list.hpp"

#include <doctest/doctest.h>

using namespace proceduray;

namespace default_global_signature_test {
struct Constants { glm::vec4 sky; float time; };
PROCEDURAY_STRUCT(Constants, scalar, sky, time);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<>, proceduray::RootComponent<Constants>, proceduray::RootArguments<>,
                                   proceduray::Attributes<>>;
using TestScene = proceduray::Scene<TestSceneInterface>;
}  // namespace default_global_signature_test

using default_global_signature_test::Constants;
using default_global_signature_test::TestScene;

TEST_CASE("default global signature binds the tlas and the image then the extras") {
  constexpr UniformSlot<Constants> constants{.binding = 2, .name = "constants"};
  const GlobalSignatureDesc d = default_global_signature({constants}, 16);
  REQUIRE(d.bindings.size() == 3);
  CHECK(d.bindings[0].kind == BindingKind::acceleration_structure);
  CHECK(d.bindings[0].binding == default_tlas_binding);
  CHECK(d.bindings[0].name == "tlas");
  CHECK(d.bindings[1].kind == BindingKind::storage_image);
  CHECK(d.bindings[1].binding == default_image_binding);
  CHECK(d.bindings[1].name == "image");
  CHECK(d.bindings[2].kind == BindingKind::uniform_buffer);
  CHECK(d.bindings[2].binding == 2);
  CHECK(d.bindings[2].type == &type_ops<Constants>);
  CHECK(d.push_constant_size == 16);
  CHECK(default_global_signature().bindings.size() == 2);
}

TEST_CASE("default global signature rejects an extra binding on its numbers") {
  TestScene scene;
  constexpr UniformSlot<Constants> clash{.binding = 1};
  CHECK_THROWS_WITH_AS(scene.add_global_signature("global", default_global_signature({clash})),
                       doctest::Contains("set 0 binding 1 twice"), DuplicateIdError);
  CHECK_NOTHROW(scene.add_global_signature("global", default_global_signature({UniformSlot<Constants>{.binding = 2}})));
}

TEST_CASE("a binding whose type is not in the scene interface's RootComponent is refused") {
  Scene<ShaderInterface<Payload<>, RootComponent<>, RootArguments<>, Attributes<>>> scene;
  CHECK_THROWS_WITH_AS(
      scene.set_global_signature(default_global_signature({UniformSlot<Constants>{.binding = 2, .name = "constants"}})),
      doctest::Contains("Scene::add_global_signature: binding \"constants\" holds default_global_signature_test::Constants, "
                        "which is not an alternative of the scene's interface; add it to its RootComponent<...> category"),
      TypeMismatchError);
  CHECK(scene.global_signatures().size() == 0);
}
