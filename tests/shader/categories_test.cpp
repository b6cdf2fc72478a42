// Tests for proceduray/shader/categories.hpp: closed sets and derived maxima.
#include <proceduray/shader/categories.hpp>

#include "test_types.hpp"

#include <doctest/doctest.h>

#include <cstring>
#include <variant>

using namespace shader_test;

TEST_CASE("the interface derives its maxima from its types") {
  static_assert(Interface::max_payload_size == sizeof(RadiancePayload));
  static_assert(Interface::max_payload_size == 16);
  static_assert(Interface::max_attribute_size == sizeof(SphereHit));
  static_assert(Interface::max_root_arguments_size == sizeof(Material430));
  static_assert(Interface::max_attribute_size <= proceduray::max_hit_attribute_size);
}

TEST_CASE("payload locations are list positions") {
  static_assert(Interface::payload_location<RadiancePayload>() == 0);
  static_assert(Interface::payload_location<ShadowPayload>() == 1);
  static_assert(Interface::root_arguments_index<Material430>() == 1);
  static_assert(Interface::attributes_index<SphereHit>() == 0);
  CHECK(Interface::root_component_index<proceduray::DeviceAddress<Sphere>>() == 1);
}

TEST_CASE("membership is known at compile time") {
  CHECK(Interface::Payloads::contains<ShadowPayload>);
  CHECK_FALSE(Interface::Payloads::contains<SphereRecord>);
  CHECK_FALSE(Interface::RootArgumentsSet::contains<RadiancePayload>);
  CHECK(Interface::AttributesSet::contains<SphereHit>);
  CHECK(proceduray::CategoryOf<Interface::Payloads, proceduray::CategoryKind::payload>);
  CHECK_FALSE(proceduray::CategoryOf<Interface::Payloads, proceduray::CategoryKind::root_arguments>);
  CHECK_FALSE(proceduray::CategoryOf<std::variant<Sphere>, proceduray::CategoryKind::payload>);
}

TEST_CASE("a category is a variant of its types") {
  Interface::Payloads payload = ShadowPayload{7};
  CHECK(payload.index() == 1);
  CHECK(std::get<ShadowPayload>(payload).occluded == 7);
  payload = RadiancePayload{glm::vec3(1.0f), 2};
  CHECK(std::visit([](const auto& p) { return sizeof(p); }, payload) == sizeof(RadiancePayload));
}

TEST_CASE("empty categories have size zero") {
  using Bare = proceduray::ShaderInterface<proceduray::Payload<ShadowPayload>, proceduray::RootComponent<>,
                                           proceduray::RootArguments<>, proceduray::Attributes<>>;
  CHECK(Bare::max_root_arguments_size == 0);
  CHECK(Bare::max_attribute_size == 0);
  CHECK(Bare::max_payload_size == 4);
  CHECK(Bare::types.size() == 1);
}

TEST_CASE("root arguments is the bytes of the root arguments") {
  const SphereRecord record{proceduray::DeviceAddress<Sphere>{0x1000}, glm::vec4(0.5f), 3, 0};
  const auto bytes = Interface::root_arguments(record);
  REQUIRE(bytes.size() == sizeof(SphereRecord));
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + offsetof(SphereRecord, count), sizeof(count));
  CHECK(count == 3);
}

TEST_CASE("the interface lists every type in category order") {
  REQUIRE(Interface::types.size() == 7);
  CHECK(Interface::types[0] == &proceduray::type_ops<RadiancePayload>);
  CHECK(Interface::types[3] == &proceduray::type_ops<proceduray::DeviceAddress<Sphere>>);
  CHECK(Interface::types[6] == &proceduray::type_ops<SphereHit>);
}
