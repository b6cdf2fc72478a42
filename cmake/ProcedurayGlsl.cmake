include_guard(GLOBAL)

# proceduray_generate_scene_glsl(<name> SOURCE <generator.cpp> OUTPUT_DIR <dir>)
#
# Writes a scene's GLSL declarations, one file per pipeline stage (proceduray/scene/glsl_files.hpp),
# into <dir> at build time: builds <generator.cpp> (whose main() returns
# proceduray::glsl_files_main(scene, argc, argv)) and runs it; no device is needed. <name> becomes
# a target in ALL, and <dir>/files.txt lists what was written: the same text a Renderer gives each
# stage at run time, for shaders compiled ahead of time (glslangValidator).
#
#   proceduray_generate_scene_glsl(my_glsl SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/my_glsl.cpp
#                                  OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/my_glsl)
function(proceduray_generate_scene_glsl name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "SOURCE;OUTPUT_DIR" "")
  foreach(required SOURCE OUTPUT_DIR)
    if(NOT arg_${required})
      message(FATAL_ERROR "proceduray_generate_scene_glsl(${name}): ${required} is missing; pass "
                          "SOURCE <generator.cpp> OUTPUT_DIR <folder>")
    endif()
  endforeach()
  if(NOT TARGET proceduray::proceduray)
    message(FATAL_ERROR "proceduray_generate_scene_glsl(${name}): target proceduray::proceduray not found; "
                        "call find_package(proceduray) first")
  endif()
  get_filename_component(dir "${arg_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  add_executable(${name}_generator "${arg_SOURCE}")
  target_link_libraries(${name}_generator PRIVATE proceduray::proceduray)
  add_custom_command(OUTPUT "${dir}/files.txt"
    COMMAND ${name}_generator "${dir}"
    DEPENDS ${name}_generator
    COMMENT "Generating the GLSL declarations of ${name} in ${dir}"
    VERBATIM)
  add_custom_target(${name} ALL DEPENDS "${dir}/files.txt")
endfunction()
