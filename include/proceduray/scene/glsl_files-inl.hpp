// The bodies of proceduray/scene/glsl_files.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/glsl_files.hpp"

#if PROCEDURAY_BODIES
#include <filesystem>
#include <fstream>
#include <iostream>
#include <exception>

namespace proceduray {

PROCEDURAY_DECL std::string glsl_file_name(ShaderStage stage, std::string_view shader) {
  std::string name(shader);
  for (char& c : name) {
    if (c == '/' || c == '\\') c = '_';
  }
  return name + "." + to_string(stage) + ".glsl";
}

PROCEDURAY_DECL std::vector<std::string> write_glsl_files(const Plan& plan, const std::string& folder) {
  const std::filesystem::path dir(folder);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  std::vector<std::string> names;
  for (const PlannedStage& stage : plan.pipeline().stages) {
    const std::string name = glsl_file_name(stage.stage, stage.shader);
    std::ofstream out(dir / name, std::ios::binary | std::ios::trunc);
    out << stage.declarations;
    if (!out.good()) {
      throw EnvironmentError("write_glsl_files: cannot write '" + (dir / name).string() +
                             "'; check that the folder is writable");
    }
    names.push_back(name);
  }
  return names;
}

PROCEDURAY_DECL int detail::glsl_files_main_core(const SceneCore& scene, int argc, char** argv) {
  if (argc >= 2 && std::string_view(argv[1]) == "--names") {
    try {
      const Plan plan = compile_core(scene);
      if (argc == 4) {
        for (const PlannedStage& stage : plan.pipeline().stages) {
          if (std::string_view(to_string(stage.stage)) == argv[2] && stage.shader == argv[3]) {
            std::cout << glsl_summary(stage.declarations);
            return 0;
          }
        }
        std::cerr << "glsl_files_main --names: the scene has no " << argv[2] << " shader \"" << argv[3]
                  << "\"; its stages are:\n";
      } else if (argc != 2) {
        std::cerr << "glsl_files_main --names: expected a stage and a shader (or nothing, for the list); got "
                  << (argc - 2) << " arguments\n";
        return 1;
      }
      for (const PlannedStage& stage : plan.pipeline().stages) {
        (argc == 2 ? std::cout : std::cerr) << to_string(stage.stage) << " " << stage.shader << "\n";
      }
      return argc == 2 ? 0 : 1;
    } catch (const std::exception& e) {
      std::cerr << e.what() << "\n";
      return 1;
    }
  }
  if (argc != 2 && argc != 3) {
    std::cerr << "glsl_files_main: expected the output folder and optionally the list file; got " << (argc - 1)
              << " arguments\n";
    return 1;
  }
  try {
    const std::vector<std::string> names = write_glsl_files(compile_core(scene), argv[1]);
    std::vector<std::filesystem::path> lists{std::filesystem::path(argv[1]) / "files.txt"};
    if (argc == 3) lists.emplace_back(argv[2]);
    for (const std::filesystem::path& path : lists) {
      std::ofstream list(path, std::ios::trunc);
      for (const std::string& name : names) list << name << "\n";
      if (!list.good()) throw EnvironmentError("glsl_files_main: cannot write " + path.string());
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
