// vk/spirv_cache.hpp: SPIR-V served from disk only while every input is unchanged; corrupt entries
// and unwritable folders warn and compile; the renderer's second start reads both caches.
#include "renderer_scene.hpp"
#include "scoped_env.hpp"
#include "test_context.hpp"
#include "test_paths.hpp"

#include <proceduray/vk/spirv_cache.hpp>

#include <cstring>
#include <fstream>

using namespace proceduray;
using renderer_scene::RendererScene;

namespace {

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

/// A fresh folder with a miss shader that includes a file of its folder.
std::filesystem::path shader_folder(const char* name) {
  const std::filesystem::path dir = test_output_dir(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "cache");
  write(dir / "tint.glsl", "vec3 tint() { return vec3(0.25); }\n");
  write(dir / "sky.rmiss",
        "#version 460\n#extension GL_EXT_ray_tracing : require\n#include \"tint.glsl\"\n"
        "layout(location = 0) rayPayloadInEXT vec3 colour;\nvoid main() { colour = tint() * SCALE; }\n");
  return dir;
}

vk::ShaderSource source(const std::filesystem::path& dir, const char* scale = "1.0") {
  return {.stage = ShaderStage::miss, .name = (dir / "sky.rmiss").string(), .code = vk::read_text_file(dir / "sky.rmiss"),
          .preamble = std::string("#define SCALE ") + scale + "\n"};
}

}  // namespace

TEST_CASE("spirv cache serves an unchanged shader from disk and recompiles when any input changes") {
  const std::filesystem::path dir = shader_folder("spirv_cache_inputs");
  vk::SpirvCache cache(dir / "cache");
  const std::vector<std::uint32_t> first = cache.compile(source(dir));
  CHECK(cache.misses() == 1);
  CHECK(std::filesystem::exists(cache.entry(source(dir))));
  CHECK(cache.compile(source(dir)) == first);
  CHECK(cache.hits() == 1);
  // A new cache over the same folder (a second start) hits too.
  vk::SpirvCache again(dir / "cache");
  CHECK(again.compile(source(dir)) == first);
  CHECK(again.hits() == 1);
  // Another define: another entry.
  CHECK(again.compile(source(dir, "2.0")) != first);
  CHECK(again.misses() == 1);
  // The included file edited: the entry is stale, compiled again, then served again.
  write(dir / "tint.glsl", "vec3 tint() { return vec3(0.5); }\n");
  const std::vector<std::uint32_t> edited = again.compile(source(dir));
  CHECK(edited != first);
  CHECK(again.misses() == 2);
  CHECK(again.compile(source(dir)) == edited);
  CHECK(again.hits() == 2);
  CHECK(again.warnings().empty());
  // Off: nothing read, nothing written.
  vk::SpirvCache off({});
  CHECK(off.compile(source(dir)) == edited);
  CHECK(off.hits() == 0);
}

TEST_CASE("spirv cache bad input: a corrupt or foreign entry is ignored with a warning and rewritten") {
  const std::filesystem::path dir = shader_folder("spirv_cache_corrupt");
  const std::vector<std::uint32_t> good = vk::SpirvCache(dir / "cache").compile(source(dir));
  const std::filesystem::path entry = vk::SpirvCache(dir / "cache").entry(source(dir));
  for (const std::string& damage : {std::string("not a cache at all"), std::string("PRYSPV01short")}) {
    CAPTURE(damage);
    write(entry, damage);
    vk::SpirvCache cache(dir / "cache");
    CHECK(cache.compile(source(dir)) == good);
    CHECK(cache.misses() == 1);
    REQUIRE(cache.warnings().size() == 1);
    CHECK(cache.warnings()[0].find("SPIR-V cache entry '" + entry.string() + "' ignored") != std::string::npos);
    CHECK(cache.warnings()[0].find("the entry rewritten") != std::string::npos);
    vk::SpirvCache after(dir / "cache");  // rewritten: served again
    CHECK(after.compile(source(dir)) == good);
    CHECK(after.hits() == 1);
  }
  // One flipped byte in the SPIR-V: the checksum catches it.
  std::string bytes;
  {
    std::ifstream in(entry, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  bytes[bytes.size() - 5] = static_cast<char>(bytes[bytes.size() - 5] ^ 0x40);
  write(entry, bytes);
  vk::SpirvCache flipped(dir / "cache");
  CHECK(flipped.compile(source(dir)) == good);
  REQUIRE(flipped.warnings().size() == 1);
  CHECK(flipped.warnings()[0].find("its checksum does not match") != std::string::npos);
}

TEST_CASE("bad input: a SPIR-V cache entry with a valid key and checksum but bad SPIR-V") {
  const std::filesystem::path dir = shader_folder("spirv_cache_bad_spirv");
  const std::vector<std::uint32_t> good = vk::SpirvCache(dir / "cache").compile(source(dir));
  const std::filesystem::path entry = vk::SpirvCache(dir / "cache").entry(source(dir));
  std::string bytes;
  {
    std::ifstream in(entry, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // The SPIR-V's id bound set to 1 (every id past it is then out of range), the checksum made right.
  const std::string spirv_magic("\x03\x02\x23\x07", 4);
  const std::size_t start = bytes.find(spirv_magic);
  REQUIRE(start != std::string::npos);
  const std::uint32_t bound = 1;
  std::memcpy(bytes.data() + start + 12, &bound, 4);
  const std::size_t sum_at = 8 + 8;  // magic, key, then the checksum of the rest
  const std::uint64_t sum = vk::fnv1a(std::string_view(bytes.data() + sum_at + 8, bytes.size() - sum_at - 8));
  std::memcpy(bytes.data() + sum_at, &sum, 8);
  write(entry, bytes);
  vk::SpirvCache cache(dir / "cache");
  CHECK(cache.compile(source(dir)) == good);  // compiled again, never handed to a driver
  CHECK(cache.misses() == 1);
  REQUIRE(cache.warnings().size() == 1);
  CHECK(cache.warnings()[0].find("SPIR-V cache entry '" + entry.string() + "' ignored (its SPIR-V does not parse") !=
        std::string::npos);
  vk::SpirvCache after(dir / "cache");  // rewritten: served again
  CHECK(after.compile(source(dir)) == good);
  CHECK(after.hits() == 1);
}

TEST_CASE("spirv cache bad input: a folder that cannot be written warns once and compiles uncached") {
  const std::filesystem::path dir = shader_folder("spirv_cache_unwritable");
  write(dir / "a_file", "x");  // a folder below a regular file cannot be made, even by root
  vk::SpirvCache cache(dir / "a_file" / "spirv");
  const std::vector<std::uint32_t> spirv = cache.compile(source(dir));
  CHECK(!spirv.empty());
  CHECK(cache.compile(source(dir)) == spirv);
  CHECK(cache.misses() == 2);
  REQUIRE(cache.warnings().size() == 1);
  CHECK(cache.warnings()[0].find("cannot be written") != std::string::npos);
  CHECK(cache.warnings()[0].find("turn the cache off (RendererOptions::cache = false)") != std::string::npos);
}

TEST_CASE("spirv cache folder follows XDG_CACHE_HOME, else HOME") {
  {
    ScopedEnv xdg("XDG_CACHE_HOME", "/somewhere/cache");
    CHECK(vk::default_cache_dir() == std::filesystem::path("/somewhere/cache/proceduray"));
  }
  ScopedEnv xdg("XDG_CACHE_HOME", "");
  ScopedEnv home("HOME", "/home/someone");
  CHECK(vk::default_cache_dir() == std::filesystem::path("/home/someone/.cache/proceduray"));
}

TEST_CASE("spirv cache: a renderer's second start reads its SPIR-V and pipeline from the cache folder") {
  TestContext t;
  RendererScene s;
  const std::filesystem::path dir = test_output_dir("spirv_cache_renderer");
  std::filesystem::remove_all(dir);
  vk::RendererOptions options = RendererScene::options();
  options.cache_dir = dir;
  std::vector<std::uint8_t> first;
  {
    vk::Renderer cold(t.ctx, s.table(t.ctx), options);
    CHECK(cold.timings().spirv_cached == 0);
    CHECK(cold.timings().spirv_compiled == 5);
    CHECK_FALSE(cold.timings().pipeline_cached);
    renderer_scene::prepare(cold, 32, 32);
    first = cold.render(32, 32).rgba;
  }
  CHECK(std::filesystem::exists(dir / vk::default_pipeline_cache_name(t.ctx)));
  vk::Renderer warm(t.ctx, s.table(t.ctx), options);
  CHECK(warm.timings().spirv_cached == 5);
  CHECK(warm.timings().spirv_compiled == 0);
  CHECK(warm.timings().pipeline_cached);
  renderer_scene::prepare(warm, 32, 32);
  CHECK(warm.render(32, 32).rgba == first);
  // cache = false: the folder is neither read nor written.
  options.cache = false;
  options.cache_dir = dir / "off";
  vk::Renderer off(t.ctx, s.table(t.ctx), options);
  CHECK(off.timings().spirv_cached == 0);
  CHECK_FALSE(std::filesystem::exists(dir / "off"));
}

TEST_CASE("spirv cache bad input: a renderer whose cache folder cannot be written warns and renders uncached") {
  TestContext t;
  RendererScene s;
  const std::filesystem::path dir = test_output_dir("spirv_cache_renderer_unwritable");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  write(dir / "a_file", "x");  // the cache folder would be below a regular file: it cannot be made
  vk::RendererOptions options = RendererScene::options();
  std::vector<std::uint8_t> uncached;
  {
    options.cache = false;
    vk::Renderer renderer(t.ctx, s.table(t.ctx), options);
    renderer_scene::prepare(renderer, 32, 32);
    uncached = renderer.render(32, 32).rgba;
  }
  options.cache = true;
  options.cache_dir = dir / "a_file" / "cache";
  vk::Renderer renderer(t.ctx, s.table(t.ctx), options);
  CHECK(renderer.timings().spirv_compiled == 5);
  CHECK_FALSE(renderer.timings().pipeline_cached);
  renderer_scene::prepare(renderer, 32, 32);
  CHECK(renderer.render(32, 32).rgba == uncached);
  CHECK_FALSE(std::filesystem::exists(dir / "a_file" / "cache"));
}
