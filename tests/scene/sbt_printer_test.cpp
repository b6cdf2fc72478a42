#include "proceduray/scene/sbt_printer.hpp"

#include "proceduray/scene/compile.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "scene_fixtures.hpp"

using namespace proceduray;
using namespace proceduray::test;
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<RayPayload, ShadowPayload>, proceduray::RootComponent<>, proceduray::RootArguments<ShadowPayload>,
                                   proceduray::Attributes<>>;
using TestScene = proceduray::Scene<TestSceneInterface>;

TEST_CASE("sbt_printer small scene prints the exact table") {
  TestScene s;
  const auto radiance = s.add_ray<RayPayload>("Radiance", {.miss = "miss"});
  const auto shadow = s.add_ray<ShadowPayload>("Shadow", {.miss = "miss_shadow"});
  const auto tri = s.add_hit_group("Tri", {.closest_hit = "chit"});
  const auto tri_shadow = s.add_hit_group("TriShadow", {});
  const auto plane = s.add_geometry("Plane", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}},
                                                                     {identity_transform(), identity_transform()}));
  const auto sig = s.add_local_signature<ShadowPayload>("Color");
  TestScene& t = s;
  t.add_raygen("rgen");
  t.add_hit(radiance, tri, sig, ShadowPayload{1}, plane);
  t.add_hit(shadow, tri_shadow, plane);
  t.add_hit(radiance, tri, sig, ShadowPayload{2}, plane, 1);
  const Plan plan = compile(t);
  const std::string text = format_sbt(plan, plan.layout(lavapipe_limits));
  const std::string expected =
      "SBT: 288 bytes; handle 32, handle alignment 16, base alignment 32; sbtRecordStride (ray types) 2\n"
      "region   | offset | stride | size | records\n"
      "---------+--------+--------+------+--------\n"
      "raygen   |      0 |     32 |   32 |       1\n"
      "miss     |     32 |     32 |   64 |       2\n"
      "hit      |     96 |     48 |  192 |       4\n"
      "callable |      0 |      0 |    0 |       0\n"
      "\n"
      "region | record | offset | group       | ray      | geometry | instance | arguments at | arguments bytes\n"
      "-------+--------+--------+-------------+----------+----------+----------+--------------+----------------\n"
      "raygen |      0 |      0 | rgen        | -        | -        | -        |           32 |               0\n"
      "miss   |      0 |     32 | miss        | Radiance | -        | -        |           64 |               0\n"
      "miss   |      1 |     64 | miss_shadow | Shadow   | -        | -        |           96 |               0\n"
      "hit    |      0 |     96 | Tri         | Radiance | Plane    | *        |          128 |               4\n"
      "hit    |      1 |    144 | TriShadow   | Shadow   | Plane    | *        |          176 |               0\n"
      "hit    |      2 |    192 | Tri         | Radiance | Plane    |        1 |          224 |               4\n"
      "hit    |      3 |    240 | TriShadow   | Shadow   | Plane    |        1 |          272 |               0\n"
      "\n"
      "TLAS instance | BLAS  | instance | sbt offset | mask\n"
      "--------------+-------+----------+------------+-----\n"
      "            0 | Plane |        0 |          0 | 0xff\n"
      "            1 | Plane |        1 |          2 | 0xff\n";
  CHECK(text == expected);
}

TEST_CASE("sbt_printer report scene lists every record and can be truncated") {
  ReportScene r;
  build_report_scene(r);
  add_report_entries(r);
  const Plan sbt = compile(r.scene);
  const SbtLayout layout = sbt.layout(h100_limits);
  const std::string text = format_sbt(sbt, layout);
  CHECK(text.find("hit    |     13 |") != std::string::npos);
  CHECK(text.find("Mandelbulb_Shadow") != std::string::npos);
  CHECK(text.find("base alignment 64") != std::string::npos);
  const std::string short_text = format_sbt(sbt, layout, 2);
  CHECK(short_text.find("(12 more)") != std::string::npos);
  CHECK(short_text.find("(5 more)") != std::string::npos);
  // PROCEDURAY_TEST_OUTPUT (set by CTest and Meson) receives the report scene's table for the docs.
  if (const char* out = std::getenv("PROCEDURAY_TEST_OUTPUT")) {
    std::filesystem::create_directories(out);
    std::ofstream(std::filesystem::path(out) / "report_scene_sbt.txt") << format_sbt(sbt, sbt.layout(lavapipe_limits));
  }
}
