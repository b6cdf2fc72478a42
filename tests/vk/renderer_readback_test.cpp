// vk/renderer.hpp (reading frames back, renderer-inl.hpp): the frame loop reads frames back as render() does, with the uniforms
// each was submitted with, allocates nothing in steady state, and refuses stale or unread frames.
#include "frame_pixels.hpp"
#include "renderer_scene.hpp"
#include "test_context.hpp"

#include <proceduray/image/png.hpp>

#include <stb_image.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

// Counts C++ allocations, so a test can show that the frame loop makes none in steady state.
// GCC sees the inlined malloc behind every `new` of this file freed by free() and warns.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
namespace {
std::atomic<std::uint64_t> allocations{0};
}
// Every non-aligned form is replaced, so every allocation and free here goes through malloc and
// free (ASan would otherwise see a library's nothrow new freed by this delete).
void* operator new(std::size_t bytes) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(bytes == 0 ? 1 : bytes)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t bytes) { return operator new(bytes); }
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(bytes == 0 ? 1 : bytes);
}
void* operator new[](std::size_t bytes, const std::nothrow_t& tag) noexcept { return operator new(bytes, tag); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

using namespace proceduray;
using renderer_scene::RendererScene;

namespace {

constexpr std::uint32_t width = 96;
constexpr std::uint32_t height = 64;

}  // namespace

TEST_CASE("renderer frame loop: frames in flight give render()'s images, each with the uniforms it was submitted with") {
  TestContext t;
  RendererScene s;
  const glm::vec4 skies[3] = {{0.9f, 0.5f, 0.1f, 1.0f}, {0.1f, 0.8f, 0.3f, 1.0f}, {0.6f, 0.2f, 0.9f, 1.0f}};
  std::vector<std::vector<std::uint8_t>> expected;
  {
    vk::Renderer blocking(t.ctx, s.table(t.ctx), RendererScene::options());
    renderer_scene::prepare(blocking, width, height);
    for (const glm::vec4& sky : skies) {
      blocking.set(renderer_scene::constants_slot, renderer_scene::constants(width, height, sky));
      expected.push_back(blocking.render(width, height).rgba);
    }
  }
  for (std::uint32_t n : {1u, 2u, 3u}) {
    CAPTURE(n);
    vk::RendererOptions options = RendererScene::options();
    options.frames_in_flight = n;
    vk::Renderer renderer(t.ctx, s.table(t.ctx), options);
    CHECK(renderer.frames_in_flight() == n);
    renderer_scene::prepare(renderer, width, height);
    // Six frames, the sky changing before each submit and none waited for until the end: each
    // frame keeps its own value (the upload is recorded in the frame, not written in place).
    std::vector<vk::FrameTicket> tickets;
    for (std::uint32_t i = 0; i < 6; ++i) {
      renderer.set(renderer_scene::constants_slot, renderer_scene::constants(width, height, skies[i % 3]));
      tickets.push_back(renderer.submit(width, height));
    }
    for (std::uint32_t i = 6 - n; i < 6; ++i) {
      const std::span<const std::uint8_t> rgba = renderer.rgba(tickets[i]);
      CHECK(std::vector<std::uint8_t>(rgba.begin(), rgba.end()) == expected[i % 3]);
      std::vector<std::uint8_t> copy(rgba.size());
      renderer.read_rgba(tickets[i], copy);
      CHECK(copy == expected[i % 3]);
      if (i == 5) {  // a PNG straight from the view, read back unchanged
        const std::filesystem::path png = test_output_dir("renderer_frame_loop") / "view.png";
        write_png(png, width, height, rgba);
        int w = 0, h = 0, channels = 0;
        unsigned char* back = stbi_load(png.string().c_str(), &w, &h, &channels, 4);
        REQUIRE(back != nullptr);
        CHECK(std::vector<std::uint8_t>(back, back + rgba.size()) == expected[i % 3]);
        stbi_image_free(back);
      }
      const vk::Frame f = renderer.wait(tickets[i]);
      CHECK(f.width == width);
      CHECK(f.trace_ms > 0.0);
      CHECK(f.rgba.empty());
    }
  }
}

TEST_CASE("renderer frame loop allocates nothing in steady state") {
  // Validation off: the layer is C++ and allocates through the same operator new. A layer forced
  // on by the environment (VK_INSTANCE_LAYERS, as on the GPU runs) would be counted too.
  const char* forced = std::getenv("VK_INSTANCE_LAYERS");
  if (forced != nullptr && std::string(forced).find("validation") != std::string::npos) {
    MESSAGE("VK_INSTANCE_LAYERS loads the validation layer, whose allocations would be counted: not checked here");
    return;
  }
  struct {
    vk::Context ctx{{.validation = false}};
  } t;
  RendererScene s;
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());
  renderer_scene::prepare(renderer, width, height);
  std::vector<std::uint8_t> pixels(std::size_t{width} * height * 4);
  const auto frame = [&](std::uint32_t i) {
    renderer.set(renderer_scene::constants_slot,
                 renderer_scene::constants(width, height, {0.1f * static_cast<float>(i % 10), 0.5f, 0.5f, 1.0f}));
    const vk::FrameTicket ticket = renderer.submit(width, height);
    renderer.read_rgba(ticket, pixels);
    return renderer.wait(ticket).trace_ms;
  };
  for (std::uint32_t i = 0; i < 5; ++i) frame(i);  // slots' readback buffers, images
  const std::uint64_t before = allocations.load();
  double traced = 0;
  for (std::uint32_t i = 0; i < 50; ++i) traced += frame(i);
  const std::uint64_t made = allocations.load() - before;  // read before CHECK, which allocates itself
  CHECK(made == 0);
  CHECK(traced > 0.0);
  CHECK(std::abs(int{pixels[0]} - 230) <= 1);  // the last frame's sky: 0.9 red (229.5, rounded either way)
}

TEST_CASE("renderer bad input: frames in flight 0 or over the limit, stale, unread and too-small reads are refused") {
  TestContext t;
  RendererScene s;
  for (std::uint32_t n : {0u, vk::max_frames_in_flight + 1}) {
    vk::RendererOptions options = RendererScene::options();
    options.frames_in_flight = n;
    const std::string expected = "RendererOptions::frames_in_flight: " + std::to_string(n) +
                                 " frames in flight asked; give 1..8";
    CHECK_THROWS_WITH_AS(vk::Renderer(t.ctx, s.table(t.ctx), options), doctest::Contains(expected.c_str()), UsageError);
  }
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());  // 2 in flight
  renderer_scene::prepare(renderer, width, height);
  const vk::FrameTicket first = renderer.submit(width, height);
  const vk::FrameTicket dark = renderer.submit(width, height, vk::Readback::none);
  renderer.submit(width, height);
  // Frame 1's slot now holds frame 3: its pixels are gone, never stale ones.
  CHECK_THROWS_WITH_AS(renderer.rgba(first), doctest::Contains("Renderer::rgba: frame 1 is gone: its slot was reused by "
                                                               "frame 3 (2 frames in flight)"),
                       UsageError);
  CHECK_THROWS_WITH_AS(renderer.wait(first), doctest::Contains("raise RendererOptions::frames_in_flight"), UsageError);
  CHECK_THROWS_WITH_AS(renderer.rgba(dark), doctest::Contains("frame 2 was submitted with Readback::none; submit it "
                                                              "with Readback::rgba"),
                       UsageError);
  CHECK_THROWS_WITH_AS(renderer.rgba(vk::FrameTicket{9, renderer.serial()}), doctest::Contains("frame 9 was never submitted (3 so far)"),
                       UsageError);
  std::vector<std::uint8_t> small(100);
  CHECK_THROWS_WITH_AS(renderer.read_rgba(vk::FrameTicket{3, renderer.serial()}, small),
                       doctest::Contains("the span holds 100 bytes but frame 3 (96x64) needs 24576 (width * height * 4)"),
                       UsageError);
  CHECK(renderer.wait(dark).trace_ms > 0.0);  // a frame without readback is still waited for and timed
}

TEST_CASE("bad input: a readback view read after a submit at a larger size replaced its slot's buffer") {
  TestContext t;
  RendererScene s;
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());  // 2 in flight
  renderer_scene::prepare(renderer, width, height);
  const vk::FrameTicket first = renderer.submit(width, height);
  const std::span<const std::uint8_t> view = renderer.rgba(first);
  const std::vector<std::uint8_t> pixels(view.begin(), view.end());
  REQUIRE(std::count(pixels.begin(), pixels.end(), std::uint8_t{0}) < std::ptrdiff_t(pixels.size()));  // not black
  renderer.submit(width, height);
  renderer.submit(2 * width, 2 * height);  // frame 1's slot, a larger buffer: the old one is kept a turn
  // Read too late (the view is documented valid for 2 submits), it still holds frame 1's pixels,
  // not freed memory (ASan checks this under the sanitizer step) nor frame 3's.
  CHECK(std::equal(view.begin(), view.end(), pixels.begin(), pixels.end()));
  CHECK_THROWS_WITH_AS(renderer.rgba(first), doctest::Contains("frame 1 is gone: its slot was reused by frame 3"),
                       UsageError);
  for (int i = 0; i < 4; ++i) renderer.submit(2 * width, 2 * height);  // a turn later the old buffer goes
  CHECK(renderer.rgba(vk::FrameTicket{7, renderer.serial()}).size() == 4 * pixels.size());
}

TEST_CASE("bad input: renderer B given renderer A's ticket, or a ticket no submit() returned") {
  TestContext t;
  RendererScene s;
  vk::Renderer a(t.ctx, s.table(t.ctx), RendererScene::options());
  vk::Renderer b(t.ctx, s.table(t.ctx), RendererScene::options());
  renderer_scene::prepare(a, width, height);
  renderer_scene::prepare(b, width, height);
  const vk::FrameTicket from_a = a.submit(width, height);
  b.submit(width, height);  // b has a frame 1 too: it must not hand back its own
  CHECK(from_a.renderer == a.serial());
  CHECK(a.serial() != b.serial());
  const std::string words = "Renderer::rgba: ticket of frame 1 was issued by renderer #" + std::to_string(a.serial()) +
                            ", not by this one (#" + std::to_string(b.serial()) + "); pass it to the renderer that submitted it";
  CHECK_THROWS_WITH_AS(b.rgba(from_a), words.c_str(), UsageError);
  CHECK_THROWS_WITH_AS(b.wait(from_a), doctest::Contains("Renderer::wait: ticket of frame 1 was issued by renderer"),
                       UsageError);
  CHECK_THROWS_WITH_AS(a.wait(vk::FrameTicket{1}), doctest::Contains("was not returned by submit() (it names no renderer)"),
                       UsageError);
  CHECK(a.wait(from_a).width == width);  // its own renderer still reads it
}

TEST_CASE("bad input: the Context destroyed (or reset) before its Renderer, which goes on rendering") {
  RendererScene s;
  auto ctx = std::make_unique<vk::Context>(vk::ContextOptions{.validation = true});
  vk::Renderer renderer(*ctx, s.table(*ctx), RendererScene::options());
  renderer_scene::prepare(renderer, width, height);
  const std::vector<std::uint8_t> before = renderer.render(width, height).rgba;
  const long shares = ctx->use_count();  // the caller's, the renderer's and its device objects'
  CHECK(shares > 2);
  ctx.reset();  // the caller's handle goes: the device stays while the renderer holds it
  CHECK(renderer.context().use_count() == shares - 1);
  const vk::FrameTicket t = renderer.submit(width, height);
  const std::span<const std::uint8_t> after = renderer.rgba(t);
  CHECK(std::vector<std::uint8_t>(after.begin(), after.end()) == before);  // the same frame, not a crash
  CHECK(std::any_of(before.begin(), before.end(), [](std::uint8_t v) { return v != 0; }));
  CHECK(renderer.context().validation_messages().empty());
}
