#include <proceduray/image/png.hpp>

#include <doctest/doctest.h>
#include <stb_image.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

using namespace proceduray;

namespace {
std::filesystem::path scratch_dir() {
  const char* env = std::getenv("PROCEDURAY_TEST_OUTPUT");
  auto dir = std::filesystem::path(env ? env : std::filesystem::temp_directory_path().string()) / "png_test";
  std::filesystem::create_directories(dir);
  return dir;
}
}  // namespace

TEST_CASE("write_png writes pixels that read back unchanged") {
  const auto path = scratch_dir() / "roundtrip.png";
  std::vector<std::uint8_t> rgba(5 * 3 * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(i * 13);
  write_png(path, 5, 3, rgba);
  int w = 0, h = 0, n = 0;
  unsigned char* back = stbi_load(path.string().c_str(), &w, &h, &n, 4);
  REQUIRE(back != nullptr);
  CHECK(w == 5);
  CHECK(h == 3);
  CHECK(std::vector<std::uint8_t>(back, back + rgba.size()) == rgba);
  stbi_image_free(back);
}

TEST_CASE("write_png rejects a pixel count that does not match the size") {
  std::vector<std::uint8_t> rgba(10);
  CHECK_THROWS_WITH_AS(write_png(scratch_dir() / "bad.png", 2, 2, rgba), doctest::Contains("needs 16"),
                       UsageError);
}

TEST_CASE("check_writable names an unwritable path and leaves no file") {
  CHECK_THROWS_WITH_AS(check_writable("/nonexistent-dir/out.png"), doctest::Contains("/nonexistent-dir/out.png"),
                       EnvironmentError);
  CHECK_THROWS_WITH_AS(check_writable(scratch_dir()), doctest::Contains("is a directory"), EnvironmentError);
  const auto fresh = scratch_dir() / "fresh.png";
  std::filesystem::remove(fresh);
  CHECK_NOTHROW(check_writable(fresh));
  CHECK_FALSE(std::filesystem::exists(fresh));
}
