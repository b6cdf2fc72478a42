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
// (docs/build_modes.md). Templates, and small bodies the compiler inlines, stay in the headers.
//
// The {fmt} way: a header declares, and its bodies sit beside it in `<header>-inl.hpp`, which the
// header includes last; that file compiles them when PROCEDURAY_BODIES is 1 (functions declared
// PROCEDURAY_DECL: `inline` header-only, external in the implementation file), with the includes
// only the bodies need. A reader of a header never scrolls through bodies.
//
// One program uses one mode, and the linker says so (ELF: Linux):
//   - a PROCEDURAY_SEPARATE file linked without implementation.hpp's file: undefined reference to
//     `proceduray_separate_mode_needs_implementation_hpp_in_one_file`;
//   - a header-only file linked with implementation.hpp's file (each would define every body):
//     multiple definition of `proceduray_header_only_and_separate_modes_mixed_in_one_program`.
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

// The link-time check of the mode (above). Symbols with C linkage: their names are the messages.
#if defined(__ELF__)
#if defined(PROCEDURAY_IMPLEMENTATION)
extern "C" {
extern const int proceduray_separate_mode_needs_implementation_hpp_in_one_file;
const int proceduray_separate_mode_needs_implementation_hpp_in_one_file = 1;
extern const int proceduray_header_only_and_separate_modes_mixed_in_one_program;
const int proceduray_header_only_and_separate_modes_mixed_in_one_program = 1;  // strong: clashes with the one below
}
#elif defined(PROCEDURAY_SEPARATE)
extern "C" const int proceduray_separate_mode_needs_implementation_hpp_in_one_file;
// A reference every separate-mode object file keeps: it links only with the implementation file.
[[gnu::used]] inline const int* const proceduray_separate_mode_reference =
    &proceduray_separate_mode_needs_implementation_hpp_in_one_file;
#else
// One copy per program (a COMDAT group) from every header-only file, a global symbol: the
// implementation file's definition of the same name is then a second one, which ld refuses.
__asm__(".pushsection .rodata.proceduray_header_only,\"aG\",@progbits,"
        "proceduray_header_only_and_separate_modes_mixed_in_one_program,comdat\n"
        ".globl proceduray_header_only_and_separate_modes_mixed_in_one_program\n"
        "proceduray_header_only_and_separate_modes_mixed_in_one_program: .byte 0\n"
        ".popsection");
#endif
#endif
