#include "proceduray/scene/ids.hpp"

#include <doctest/doctest.h>

#include <type_traits>

using namespace proceduray;

namespace {
struct A {};
struct B {};
}  // namespace

static_assert(!std::is_convertible_v<GeometryId, HitGroupId>, "ids of different kinds never mix");
static_assert(!std::is_convertible_v<std::uint32_t, GeometryId>, "raw integers are not ids");
static_assert(std::is_convertible_v<RayId<A>, RayId<>>, "typed ids convert to untyped ones");
static_assert(!std::is_convertible_v<RayId<A>, RayId<B>>, "payload types never mix");
static_assert(!std::is_convertible_v<RayId<>, RayId<A>>, "an untyped id does not become typed");
static_assert(!std::is_convertible_v<LocalSignatureId<A>, LocalSignatureId<B>>);
static_assert(sizeof(GeometryId) == 2 * sizeof(std::uint32_t), "an index and the issuing scene's serial");

TEST_CASE("ids default to invalid and compare by index") {
  constexpr GeometryId none;
  CHECK_FALSE(none.valid());
  CHECK(GeometryId(3).valid());
  CHECK(GeometryId(3) == GeometryId(3));
  CHECK(GeometryId(2) < GeometryId(3));
  const RayId<> untyped = RayId<A>(5, 9);
  CHECK(untyped.index() == 5);
  CHECK(untyped.scene() == 9);  // the conversion keeps the issuing scene
  CHECK(GeometryId(3, 1) == GeometryId(3, 2));  // equality is by index: a plan's ids equal the scene's
}
