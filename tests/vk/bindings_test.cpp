// vk/bindings.hpp: typed slots are checked against the global signature, so a value of another
// type is refused instead of writing past its buffer (or leaving a black image).
#include "renderer_scene.hpp"
#include "test_context.hpp"

using namespace proceduray;

namespace bindings_test {
struct Big {  // larger than renderer_scene::Constants
  glm::mat4 m[4];
};
PROCEDURAY_STRUCT(Big, scalar, m);
struct Small {
  float x;
};
PROCEDURAY_STRUCT(Small, scalar, x);
}  // namespace bindings_test

TEST_CASE("bindings refuse a slot whose type or place the global signature does not declare") {
  TestContext t;
  renderer_scene::RendererScene s;
  const Plan plan = compile(s.table(t.ctx));
  vk::SceneAcceleration structures(t.ctx, plan);
  vk::Bindings bindings(t.ctx, plan.global_signature(), structures.tlas().structure());
  constexpr UniformSlot<bindings_test::Big> big{.binding = 2, .name = "constants"};
  CHECK_THROWS_WITH_AS(bindings.set(big, bindings_test::Big{}),
                       doctest::Contains("Bindings::set: set 0 binding 2 holds Constants in the global signature, not Big"),
                       UsageError);
  constexpr StorageSlot<bindings_test::Small> small{.binding = 3, .name = "tints"};
  const bindings_test::Small one[] = {{1.0f}};
  CHECK_THROWS_WITH_AS(bindings.set_storage(small, std::span<const bindings_test::Small>(one)),
                       doctest::Contains("set 0 binding 3 holds Tint in the global signature, not Small"), UsageError);
  constexpr UniformSlot<renderer_scene::Constants> elsewhere{.binding = 7, .name = "constants"};
  CHECK_THROWS_WITH_AS(bindings.set(elsewhere, renderer_scene::Constants{}),
                       doctest::Contains("set 0 binding 7 is not a uniform buffer of the global signature"), UsageError);
  // The right slots still work, and then nothing is missing.
  bindings.set(renderer_scene::constants_slot, renderer_scene::constants(8, 8));
  const renderer_scene::Tint white[] = {{glm::vec4(1.0f)}};
  bindings.set_storage(renderer_scene::tints_slot, std::span<const renderer_scene::Tint>(white));
  CHECK_NOTHROW(bindings.check_ready("test"));
  CHECK(bindings.sets().size() == 1);
  CHECK(bindings.push_size() == 0);
}
