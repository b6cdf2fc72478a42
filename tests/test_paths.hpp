// Where tests find their data: $PROCEDURAY_TEST_SOURCE_DIR, else the tests/ folder known at build time.
//
//   auto dir = test_source_dir() / "vk" / "shaders";
#pragma once

#include <cstdlib>
#include <filesystem>

inline std::filesystem::path test_source_dir() {
  if (const char* env = std::getenv("PROCEDURAY_TEST_SOURCE_DIR"); env != nullptr && *env != '\0') return env;
  return PROCEDURAY_TEST_SOURCE_DIR;
}

/// A scratch folder for files tests write: $PROCEDURAY_TEST_OUTPUT, else the system temp folder.
inline std::filesystem::path test_output_dir(const char* name) {
  const char* env = std::getenv("PROCEDURAY_TEST_OUTPUT");
  auto dir = std::filesystem::path(env ? env : std::filesystem::temp_directory_path().string()) / name;
  std::filesystem::create_directories(dir);
  return dir;
}
