# Compiles one source that must not compile and checks that every `// expect: TEXT` line of the
# source appears in the compiler's diagnostics. A source with `// expect-success` must compile.
# The wording around our messages differs between compilers: `// expect-gcc:` and
# `// expect-clang:` lines are checked with that compiler only, and an `// expect:` line's
# "static assertion failed: " (GCC's prefix; clang writes `static_assert failed "...`) is dropped
# for clang, which leaves the message our static_assert wrote.
#   cmake -DCOMPILER=g++ "-DFLAGS=-std=c++20;-I..." -DSOURCE=file.cpp -P check_compile_fail.cmake
if(NOT COMPILER OR NOT SOURCE)
  message(FATAL_ERROR "check_compile_fail: pass -DCOMPILER=<c++ compiler> -DSOURCE=<file>")
endif()
separate_arguments(compiler_cmd UNIX_COMMAND "${COMPILER}")
execute_process(COMMAND ${compiler_cmd} ${FLAGS} -fsyntax-only ${SOURCE}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
string(FIND "${COMPILER}" "clang" clang_at)
if(clang_at EQUAL -1)
  file(STRINGS ${SOURCE} expects REGEX "^// expect(-gcc)?: ")
else()
  file(STRINGS ${SOURCE} expects REGEX "^// expect(-clang)?: ")
endif()
file(STRINGS ${SOURCE} success REGEX "^// expect-success")
if(success)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${SOURCE} should compile but failed:\n${out}")
  endif()
  message(STATUS "${SOURCE} compiles, as expected")
  return()
endif()
if(rc EQUAL 0)
  message(FATAL_ERROR "${SOURCE} compiled but must not")
endif()
if(NOT expects)
  message(FATAL_ERROR "${SOURCE} has no `// expect: TEXT` line")
endif()
foreach(line IN LISTS expects)
  string(REGEX REPLACE "^// expect(-gcc|-clang)?: " "" text "${line}")
  if(NOT clang_at EQUAL -1)
    string(REGEX REPLACE "^static assertion failed: " "" text "${text}")
  endif()
  string(FIND "${out}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${SOURCE}: the diagnostics lack \"${text}\":\n${out}")
  endif()
  message(STATUS "found: ${text}")
endforeach()
