// How the library's function bodies are compiled: inline in every file (the default, header-only)
// or once, in one implementation file of the program.
//
//   // Header-only (default): include and go; nothing to link.
//   #include <proceduray/proceduray.hpp>
//
//   // Compiled once: define PROCEDURAY_SEPARATE for every file of the program (best as a compile
//   // definition of the target, e.g. target_compile_definitions(app PRIVATE PROCEDURAY_SEPARATE)),
//   // and add one .cpp that holds the bodies:
//   #include <proceduray/implementation.hpp>   // proceduray.cpp: this line only
//
// Why: the vk/ bodies, glslang's headers and the file I/O behind them cost a file that includes the
// renderer about 20 s at -O2 when every file compiles them; declared only, they cost a few seconds
// (README: "Compile time"). Templates, and small bodies the compiler inlines, stay in the headers.
//
// Headers mark what moves: a function declared PROCEDURAY_DECL and defined below in an
// `#if PROCEDURAY_BODIES` block, and includes only those bodies need inside the same block.
// One program uses one mode: a header-only file linked with implementation.hpp's would define
// each body twice. A PROCEDURAY_SEPARATE program without implementation.hpp fails to link,
// naming the first body it misses (e.g. proceduray::vk::Renderer::Renderer).
#pragma once

#if defined(PROCEDURAY_IMPLEMENTATION)
#define PROCEDURAY_BODIES 1
#define PROCEDURAY_DECL  // external linkage: this file is the one that defines them
#elif defined(PROCEDURAY_SEPARATE)
#define PROCEDURAY_BODIES 0
#define PROCEDURAY_DECL
#else
#define PROCEDURAY_BODIES 1
#define PROCEDURAY_DECL inline
#endif
