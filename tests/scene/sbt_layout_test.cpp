#include "proceduray/scene/sbt_layout.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

#include "scene_fixtures.hpp"

using namespace proceduray;
using proceduray::test::check_layout_invariants;

TEST_CASE("sbt_layout lavapipe: handle alignment below handle size") {
  const SbtProperties p = test::lavapipe_limits.sbt;
  const std::array<SbtRegionRecords, 4> in{{{1, 0}, {2, 0}, {4, 8}, {}}};
  const SbtLayout l = layout_sbt(p, in);
  check_layout_invariants(l, in);
  CHECK(l.region(SbtRegionKind::raygen).offset == 0);
  CHECK(l.region(SbtRegionKind::raygen).stride == 32);
  CHECK(l.region(SbtRegionKind::miss).offset == 32);
  CHECK(l.region(SbtRegionKind::miss).stride == 32);
  CHECK(l.region(SbtRegionKind::hit).offset == 96);
  CHECK(l.region(SbtRegionKind::hit).stride == 48);  // 32 + 8 -> multiple of 16, not of 32
  CHECK(l.region(SbtRegionKind::hit).size == 192);
  CHECK(l.size == 288);
  CHECK(l.arguments_offset(SbtRegionKind::hit, 3) == 96 + 3 * 48 + 32);
}

TEST_CASE("sbt_layout h100: stride and regions follow the 32 and 64 alignments") {
  const SbtProperties p = test::h100_limits.sbt;
  const std::array<SbtRegionRecords, 4> in{{{1, 4}, {2, 0}, {22, 48}, {}}};
  const SbtLayout l = layout_sbt(p, in);
  check_layout_invariants(l, in);
  CHECK(l.region(SbtRegionKind::raygen).stride == 64);
  CHECK(l.region(SbtRegionKind::raygen).size == 64);
  CHECK(l.region(SbtRegionKind::miss).offset == 64);
  CHECK(l.region(SbtRegionKind::miss).stride == 32);
  CHECK(l.region(SbtRegionKind::hit).offset == 128);
  CHECK(l.region(SbtRegionKind::hit).stride == 96);
  CHECK(l.size == 128 + 22 * 96);
}

TEST_CASE("sbt_layout synthetic profiles: handle 64 align 64 base 256") {
  const std::array<SbtRegionRecords, 4> in{{{2, 16}, {3, 0}, {5, 100}, {1, 4}}};
  const SbtLayout l = layout_sbt(test::synthetic_64_64_256, in);
  check_layout_invariants(l, in);
  CHECK(l.region(SbtRegionKind::raygen).stride == 256);
  CHECK(l.region(SbtRegionKind::miss).offset == 512);
  CHECK(l.region(SbtRegionKind::hit).offset == 768);
  CHECK(l.region(SbtRegionKind::hit).stride == 192);
  CHECK(l.region(SbtRegionKind::callable).offset == 768 + 5 * 192 + 64);  // 1728 -> next multiple of 256
  CHECK(l.region(SbtRegionKind::callable).offset % 256 == 0);
}

TEST_CASE("sbt_layout random records hold the invariants on every profile") {
  std::mt19937 rng(1234);
  for (const SbtProperties& p : test::all_sbt_profiles()) {
    for (int n = 0; n < 300; ++n) {
      std::array<SbtRegionRecords, 4> in{};
      for (std::uint32_t k = 0; k < 4; ++k) {
        in[k].count = (k == 0 ? 1u : 0u) + rng() % 20;
        in[k].max_arguments_size = rng() % 4 == 0 ? 0u : static_cast<std::uint32_t>(rng() % (p.max_stride - p.base_alignment - p.handle_size));
      }
      const SbtLayout l = layout_sbt(p, in);
      check_layout_invariants(l, in);
    }
  }
}

TEST_CASE("sbt_layout root arguments written at arguments offsets never overlaps another record") {
  for (const SbtProperties& p : test::all_sbt_profiles()) {
    const std::array<SbtRegionRecords, 4> in{{{2, 12}, {3, 20}, {7, 36}, {2, 4}}};
    const SbtLayout l = layout_sbt(p, in);
    std::vector<int> owner(l.size, -1);
    int id = 0;
    for (std::uint32_t k = 0; k < 4; ++k) {
      for (std::uint32_t i = 0; i < in[k].count; ++i, ++id) {
        const auto kind = static_cast<SbtRegionKind>(k);
        const std::uint64_t begin = l.record_offset(kind, i);
        const std::uint64_t end = l.arguments_offset(kind, i) + in[k].max_arguments_size;
        REQUIRE(end <= l.size);
        for (std::uint64_t b = begin; b < end; ++b) {
          CHECK(owner[b] == -1);
          owner[b] = id;
        }
      }
    }
    CHECK(id == 14);
  }
}

TEST_CASE("sbt_layout stride above the device maximum names both numbers") {
  CHECK_THROWS_WITH_AS(layout_sbt(test::h100_limits.sbt, {{{1, 0}, {1, 0}, {1, 4096}, {}}}),
                       doctest::Contains("hit record stride 4128 bytes"), DeviceLimitError);
  CHECK_THROWS_WITH_AS(layout_sbt(test::h100_limits.sbt, {{{1, 0}, {1, 0}, {1, 4096}, {}}}),
                       doctest::Contains("maxShaderGroupStride 4096"), DeviceLimitError);
  // The same data fits lavapipe's 16384.
  CHECK(layout_sbt(test::lavapipe_limits.sbt, {{{1, 0}, {1, 0}, {1, 4096}, {}}}).region(SbtRegionKind::hit).stride == 4128);
  // Raygen strides round to the base alignment: 4064 + 32 fits 4096 on H100, 4065 does not.
  CHECK(layout_sbt(test::h100_limits.sbt, {{{1, 4032}, {}, {}, {}}}).region(SbtRegionKind::raygen).stride == 4096);
  CHECK_THROWS_AS(layout_sbt(test::h100_limits.sbt, {{{1, 4065}, {}, {}, {}}}), DeviceLimitError);
}

TEST_CASE("sbt_layout rejects impossible properties and an empty raygen region") {
  CHECK_THROWS_WITH_AS(layout_sbt({.handle_size = 32, .handle_alignment = 24, .base_alignment = 64, .max_stride = 4096},
                                  {{{1, 0}, {}, {}, {}}}),
                       doctest::Contains("powers of two"), UsageError);
  CHECK_THROWS_AS(layout_sbt({.handle_size = 32, .handle_alignment = 64, .base_alignment = 32, .max_stride = 4096},
                             {{{1, 0}, {}, {}, {}}}),
                  UsageError);
  CHECK_THROWS_AS(layout_sbt({.handle_size = 0}, {{{1, 0}, {}, {}, {}}}), UsageError);
  CHECK_THROWS_WITH_AS(layout_sbt(test::lavapipe_limits.sbt, {{{0, 0}, {1, 0}, {1, 0}, {}}}),
                       doctest::Contains("raygen region is empty"), UsageError);
}

TEST_CASE("sbt_layout record_offset past the region count throws") {
  const SbtLayout l = layout_sbt(test::lavapipe_limits.sbt, {{{1, 0}, {2, 0}, {}, {}}});
  CHECK(l.record_offset(SbtRegionKind::miss, 1) == 64);
  CHECK_THROWS_WITH_AS(l.record_offset(SbtRegionKind::miss, 2), doctest::Contains("miss record 2 does not exist"),
                       UsageError);
  CHECK_THROWS_AS(l.arguments_offset(SbtRegionKind::hit, 0), UsageError);
}

namespace {
std::uint64_t json_number(const std::string& text, const std::string& key) {
  const std::regex re("\"" + key + "\"\\s*:\\s*([0-9]+)");
  std::smatch m;
  REQUIRE_MESSAGE(std::regex_search(text, m, re), "key " << key);
  return std::stoull(m[1].str());
}
}  // namespace

TEST_CASE("sbt_layout profile constants match shared device-profiles when present") {
  // tests/scene/<this file> -> repository root -> ../shared/device-profiles (CI clones shared/ beside the repo).
  const std::filesystem::path dir =
      std::filesystem::path(__FILE__).parent_path().parent_path().parent_path().parent_path() / "shared" / "device-profiles";
  if (!std::filesystem::is_directory(dir)) {
    MESSAGE("no " << dir.string() << ": profile constants not cross-checked");
    return;
  }
  int matched = 0;
  for (const auto& file : std::filesystem::directory_iterator(dir)) {
    if (file.path().extension() != ".json") continue;
    std::ifstream in(file.path());
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    DeviceLimits l;
    l.sbt.handle_size = static_cast<std::uint32_t>(json_number(text, "shaderGroupHandleSize"));
    l.sbt.handle_alignment = static_cast<std::uint32_t>(json_number(text, "shaderGroupHandleAlignment"));
    l.sbt.base_alignment = static_cast<std::uint32_t>(json_number(text, "shaderGroupBaseAlignment"));
    l.sbt.max_stride = static_cast<std::uint32_t>(json_number(text, "maxShaderGroupStride"));
    l.max_ray_recursion_depth = static_cast<std::uint32_t>(json_number(text, "maxRayRecursionDepth"));
    l.max_ray_hit_attribute_size = static_cast<std::uint32_t>(json_number(text, "maxRayHitAttributeSize"));
    l.max_geometry_count = json_number(text, "maxGeometryCount");
    l.max_instance_count = json_number(text, "maxInstanceCount");
    const std::string name = file.path().filename().string();
    INFO(name);
    const DeviceLimits& expected = name.find("lavapipe") != std::string::npos ? test::lavapipe_limits
                                   : name.find("h200") != std::string::npos   ? test::h200_limits
                                                                              : test::h100_limits;
    CHECK(l.sbt.handle_size == expected.sbt.handle_size);
    CHECK(l.sbt.handle_alignment == expected.sbt.handle_alignment);
    CHECK(l.sbt.base_alignment == expected.sbt.base_alignment);
    CHECK(l.sbt.max_stride == expected.sbt.max_stride);
    CHECK(l.max_ray_recursion_depth == expected.max_ray_recursion_depth);
    CHECK(l.max_ray_hit_attribute_size == expected.max_ray_hit_attribute_size);
    CHECK(l.max_geometry_count == expected.max_geometry_count);
    CHECK(l.max_instance_count == expected.max_instance_count);
    // Every measured profile lays out a table that holds the invariants.
    const std::array<SbtRegionRecords, 4> records{{{1, 8}, {2, 16}, {22, 48}, {}}};
    check_layout_invariants(layout_sbt(l.sbt, records), records);
    ++matched;
  }
  CHECK(matched >= 3);
}
