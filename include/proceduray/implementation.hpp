// The one file of a PROCEDURAY_SEPARATE program that compiles the library's bodies (config.hpp).
//
//   // proceduray.cpp, built with the rest of the program (PROCEDURAY_SEPARATE defined or not):
//   #include <proceduray/implementation.hpp>
//
// It must come before any other Proceduray header in that file: config.hpp is read once, so a
// header included earlier would have fixed the bodies as declared only.
#pragma once

#ifdef PROCEDURAY_BODIES
#error "include <proceduray/implementation.hpp> before any other Proceduray header in its file"
#endif
#ifndef PROCEDURAY_IMPLEMENTATION
#define PROCEDURAY_IMPLEMENTATION
#endif
#include <proceduray/proceduray.hpp>
