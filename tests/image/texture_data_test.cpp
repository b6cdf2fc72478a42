// image/texture_data.hpp: files read through stb_image come back as the pixels written, channel
// counts expand to RGBA, cube faces are checked, and bad files and values name the fix.
#include <proceduray/image/png.hpp>
#include <proceduray/image/texture_data.hpp>

#include <doctest/doctest.h>
#include <stb_image_write.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

using namespace proceduray;

namespace {

std::filesystem::path scratch_dir() {
  const char* env = std::getenv("PROCEDURAY_TEST_OUTPUT");
  auto dir = std::filesystem::path(env ? env : std::filesystem::temp_directory_path().string()) / "texture_data_test";
  std::filesystem::create_directories(dir);
  return dir;
}

std::uint8_t texel8(const TextureData& t, std::size_t texel, int channel) {
  return static_cast<std::uint8_t>(t.pixels[4 * texel + static_cast<std::size_t>(channel)]);
}
float texel32(const TextureData& t, std::size_t texel, int channel) {
  float v;
  std::memcpy(&v, t.pixels.data() + 16 * texel + 4 * static_cast<std::size_t>(channel), 4);
  return v;
}

}  // namespace

TEST_CASE("texture data: a PNG reads back as the RGBA8 sRGB pixels written") {
  const auto path = scratch_dir() / "four.png";
  std::vector<std::uint8_t> rgba(4 * 2 * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(7 * i + 3);
  write_png(path, 4, 2, rgba);
  const TextureData t = load_texture(path);
  CHECK(t.width == 4);
  CHECK(t.height == 2);
  CHECK(t.faces == 1);
  CHECK(t.format == TexelFormat::rgba8);
  CHECK(t.srgb);
  REQUIRE(t.pixels.size() == rgba.size());
  CHECK(std::memcmp(t.pixels.data(), rgba.data(), rgba.size()) == 0);
  CHECK(t.mip_levels() == 3);  // 4x2, 2x1, 1x1
}

TEST_CASE("texture data: an HDR file reads back as linear float RGBA") {
  const auto path = scratch_dir() / "bright.hdr";
  const float rgb[] = {4.0f, 0.5f, 0.25f, 1.0f, 2.0f, 8.0f};  // two texels, values Radiance HDR stores exactly
  REQUIRE(stbi_write_hdr(path.string().c_str(), 2, 1, 3, rgb) != 0);
  const TextureData t = load_texture(path);
  CHECK(t.format == TexelFormat::rgba32f);
  CHECK_FALSE(t.srgb);
  REQUIRE(t.pixels.size() == 2 * 16);
  CHECK(texel32(t, 0, 0) == doctest::Approx(4.0f));
  CHECK(texel32(t, 0, 1) == doctest::Approx(0.5f));
  CHECK(texel32(t, 1, 2) == doctest::Approx(8.0f));
  CHECK(texel32(t, 1, 3) == 1.0f);  // alpha added
}

TEST_CASE("texture data: a JPEG reads back as RGBA8 sRGB, within its compression's error") {
  const auto path = scratch_dir() / "flat.jpg";
  std::vector<std::uint8_t> rgb;
  for (int i = 0; i < 16 * 16; ++i) rgb.insert(rgb.end(), {200, 120, 40});
  REQUIRE(stbi_write_jpg(path.string().c_str(), 16, 16, 3, rgb.data(), 95) != 0);
  const TextureData t = load_texture(path);
  CHECK(t.format == TexelFormat::rgba8);
  CHECK(t.srgb);
  REQUIRE(t.width == 16);
  REQUIRE(t.pixels.size() == 16 * 16 * 4);
  for (std::size_t texel : {std::size_t{0}, std::size_t{137}, std::size_t{255}}) {
    CHECK(std::abs(int{texel8(t, texel, 0)} - 200) <= 4);  // a flat block survives JPEG almost exactly
    CHECK(std::abs(int{texel8(t, texel, 1)} - 120) <= 4);
    CHECK(std::abs(int{texel8(t, texel, 2)} - 40) <= 4);
    CHECK(texel8(t, texel, 3) == 255);
  }
}

TEST_CASE("texture data: 1 to 4 channels expand to RGBA, others are refused") {
  const std::uint8_t grey[] = {10, 20};
  const TextureData g = TextureData::from_pixels(2, 1, 1, grey);
  CHECK(texel8(g, 1, 0) == 20);
  CHECK(texel8(g, 1, 1) == 20);
  CHECK(texel8(g, 1, 2) == 20);
  CHECK(texel8(g, 1, 3) == 255);
  const std::uint8_t grey_alpha[] = {10, 99, 20, 77};
  CHECK(texel8(TextureData::from_pixels(2, 1, 2, grey_alpha), 1, 3) == 77);
  const std::uint8_t rgb[] = {1, 2, 3, 4, 5, 6};
  const TextureData c = TextureData::from_pixels(2, 1, 3, rgb);
  CHECK(texel8(c, 1, 0) == 4);
  CHECK(texel8(c, 1, 2) == 6);
  CHECK(texel8(c, 1, 3) == 255);
  const float hdr[] = {0.5f, 2.0f};
  const TextureData f = TextureData::from_pixels(2, 1, 1, std::span<const float>(hdr));
  CHECK(f.format == TexelFormat::rgba32f);
  CHECK(texel32(f, 1, 1) == 2.0f);
  const std::uint8_t five[10]{};
  CHECK_THROWS_WITH_AS(TextureData::from_pixels(2, 1, 5, five),
                       doctest::Contains("TextureData::from_pixels: 5 channels; a texture takes 1 (grey)"), UsageError);
  CHECK_THROWS_WITH_AS(TextureData::from_pixels(2, 2, 3, rgb),
                       doctest::Contains("6 values for 2x2 texels of 3 channels (need 12"), UsageError);
  CHECK_THROWS_AS(TextureData::from_pixels(0, 1, 1, std::span<const std::uint8_t>()), UsageError);
}

TEST_CASE("texture data: a cube takes six square faces of one size and format, in order") {
  std::vector<TextureData> faces;
  for (std::uint8_t i = 0; i < 6; ++i) {
    const std::vector<std::uint8_t> v(4, static_cast<std::uint8_t>(40 * i));
    faces.push_back(TextureData::from_pixels(2, 2, 1, v));
  }
  const TextureData cube = make_cube(faces);
  CHECK(cube.cube());
  CHECK(cube.faces == 6);
  REQUIRE(cube.pixels.size() == 6 * cube.face_bytes());
  for (std::size_t f = 0; f < 6; ++f) CHECK(texel8(cube, 4 * f, 0) == 40 * f);  // face after face
  std::vector<TextureData> wrong = faces;
  const std::vector<std::uint8_t> big(16, 0);
  wrong[3] = TextureData::from_pixels(4, 4, 1, big);
  CHECK_THROWS_WITH_AS(make_cube(wrong), doctest::Contains("make_cube: face 3 is 4x4 rgba8, face 0 is 2x2 rgba8"),
                       UsageError);
  const std::vector<std::uint8_t> flat(8, 0);
  wrong[3] = TextureData::from_pixels(4, 2, 1, flat);
  CHECK_THROWS_WITH_AS(make_cube(wrong), doctest::Contains("cube faces are square"), UsageError);
  CHECK_THROWS_WITH_AS(make_cube(std::span<const TextureData>(faces.data(), 5)),
                       doctest::Contains("make_cube: 5 faces; a cube map has six"), UsageError);
}

TEST_CASE("texture data: a missing or undecodable file throws EnvironmentError naming it") {
  const auto missing = scratch_dir() / "absent.png";
  std::filesystem::remove(missing);
  CHECK_THROWS_WITH_AS(load_texture(missing), doctest::Contains("absent.png' is not a file"), EnvironmentError);
  CHECK_THROWS_WITH_AS(load_texture(scratch_dir()), doctest::Contains("is not a file"), EnvironmentError);
  const auto garbage = scratch_dir() / "garbage.png";
  std::ofstream(garbage, std::ios::binary) << "this is not an image";
  CHECK_THROWS_WITH_AS(load_texture(garbage), doctest::Contains("load_texture: cannot decode"), EnvironmentError);
  CHECK_THROWS_WITH_AS(load_texture(garbage), doctest::Contains("garbage.png"), EnvironmentError);
}
